"""Hertz contact by mpmath: independent high-precision reference (not derived from the crate).

G(m) = (1 - m) D(m) / B(m) with B = (E - (1-m)K)/m, D = (K - E)/m, parameter m = e^2.
Solve G(m) = g with findroot at the working precision (dps >= 30).
"""
import mpmath as mp

mp.mp.dps = 40


def bd(m):
    """B(m), D(m) by quadrature-free closed forms (mpmath's ellipk/ellipe), or series at m=0."""
    m = mp.mpf(m)
    if m == 0:
        return mp.pi / 4, mp.pi / 4
    k, e = mp.ellipk(m), mp.ellipe(m)
    return (e - (1 - m) * k) / m, (k - e) / m


def big_g(m):
    b, d = bd(m)
    return (1 - m) * d / b


def solve_c(g):
    """c = e^2 with G(c) = g, g in (0, 1]. Solved in s = ln(1 - c) for robustness near c -> 1."""
    g = mp.mpf(g)
    if g == 1:
        return mp.mpf(0)
    if g > mp.mpf("0.5"):
        # small c: solve in c directly from the series start c ~ 4(1-g)/3
        c0 = 4 * (1 - g) / 3
        return mp.findroot(lambda c: big_g(c) - g, c0, tol=mp.mpf(10) ** (-2 * mp.mp.dps + 20))
    k0 = (1 / g) ** (2 / mp.pi)
    s0 = mp.log(1 / k0**2)
    s = mp.findroot(lambda s: mp.log(big_g(1 - mp.exp(s))) - mp.log(g), s0,
                    tol=mp.mpf(10) ** (-2 * mp.mp.dps + 20))
    return 1 - mp.exp(s)


def shape(g):
    """(c, m1, K, E, B, D) at g with m1 = 1 - c."""
    c = solve_c(g)
    m1 = 1 - c
    b, d = bd(c)
    return c, m1, b + d, b + m1 * d, b, d


def hertz(p, q, estar, h, c=None):
    """(c, a, b, N) from model.md section 1: a^2 = h D/(P K), b^2 = (1-c) a^2,
    N = kH h^{3/2}, kH = (2 pi/3) E* sqrt(D/P) / K^{3/2}."""
    p, q, estar, h = (mp.mpf(x) for x in (p, q, estar, h))
    if c is None:
        c = solve_c(p / q)
    b_, d_ = bd(c)
    k = b_ + d_
    a = mp.sqrt(h * d_ / (p * k))
    b = mp.sqrt(1 - c) * a
    kh = 2 * mp.pi / 3 * estar * mp.sqrt(d_ / p) / k ** mp.mpf(1.5)
    n = kh * h ** mp.mpf(1.5)
    return c, a, b, n
