#!/usr/bin/env python3
"""M4F f32 cost estimates (instructions; VDIV/VSQRT 14 cycles each) of the corrections tried in /tmp/cap/cap.py.

Convention of docs/guide/src/rolling.md: a polynomial term ≈ 1 monomial product + 3 coefficient loads + 3 FMAs
(≈ 8 instructions with the monomial's own load/store); a gated copy of the same monomials adds 6 per term
(its sum is multiplied by the gate once); the relative block P_k(x)·τ²·D_k adds 3 × 6 per term of its own degree.
MLP: n_in·h + h² + 3h multiply-adds (load + FMA = 2 each) and 2h tanh (rational form, ≈ 20 with one VDIV).
Features (13 base: Ŵ_lin normalisation, σ, λ, τ, ln(major/minor), cos/sin 2ψ, W_fs passed in) ≈ 120 + 1 log, 2 div, 1 sqrt;
+W_base: free (already computed); + 4 rbf bumps in ln ρ: 4 exp (≈ 25 each) + 1 log.
The BASE is not included: two full slips `best` 504 + reach ≈ 150 (docs), + the 1-D strip base
(3 marches × 64 steps, each a hypot and a division: ≈ 3 × 64 × 25 ≈ 4,800 and 192 sqrt + 192 div as prototyped).
"""
from math import comb


def poly(nf, deg):
    return comb(nf + deg, deg)


def poly_cost(nf, deg, gate_copies=0, gate_deg=None, rel_deg=None, feat=120):
    m = poly(nf, deg)
    c = 8 * m
    if gate_copies:
        mg = poly(nf, gate_deg or deg)
        c += gate_copies * (6 * mg + 3 + 30)  # + the gate's logistic (one exp)
    if rel_deg is not None:
        c += 18 * poly(nf, rel_deg)
    return c + feat


def mlp_cost(nin, h, feat=120):
    mac = nin * h + h * h + 3 * h
    return 2 * mac + 2 * h * 20 + feat, mac, 2 * h


rows = [("log (reference)", poly_cost(13, 3)), ("+wb", poly_cost(16, 3)), ("+wb+fss", poly_cost(19, 3) + 30),
        ("+all (wb,fss,pole,lnrho)", poly_cost(22, 3) + 60), ("+all+uc", poly_cost(25, 3) + 80),
        ("+wb+fss rel1", poly_cost(19, 3, rel_deg=1)), ("+wb rel2", poly_cost(16, 3, rel_deg=2)),
        ("+wb+rbf rel2", poly_cost(20, 3, rel_deg=2) + 130), ("log deg4 rel2", poly_cost(13, 4, rel_deg=2)),
        ("gate σ deg2, +wb rel2", poly_cost(16, 3, 1, 2, 2)), ("gate σ+ρ deg2, +wb rel2", poly_cost(16, 3, 2, 2, 2)),
        ("gate σ deg3, +wb rel2", poly_cost(16, 3, 1, 3, 2)),
        ("sparse 100 terms", 8 * 100 + 120), ("sparse 150 terms", 8 * 150 + 120)]
for nin, h in [(13, 12), (13, 16), (16, 16), (13, 24), (16, 24), (16, 32)]:
    c, mac, th = mlp_cost(nin, h)
    rows.append((f"MLP {nin}→{h}→{h}→3 ({mac} MAC, {th} tanh/div)", c))
for n, c in rows:
    print(f"{n:45s} ≈ {c:6d} instr (correction + features; base excluded)")
