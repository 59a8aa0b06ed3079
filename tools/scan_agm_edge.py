#!/usr/bin/env python3
"""Dense scan of the AGM's f64 K and E near the domain edge m -> 1 against mpmath (the figure
"1.5e-15 over scans of 3,000 and 12,000 m1" in src/elliptic/agm.rs): N values m1 log-spaced
over [1e-12, 10^(-12 + DECADES)], each rounded up to a multiple of 2^-53 (m = 1 - m1 exact),
evaluated by `contact_eval elliptic --method agm` and compared with mpmath's ellipk/ellipe at
40 digits. Prints the max relative errors of K and E and the m1 of E's maximum.

Run from the repository root (after `cargo build --release --bin contact_eval`):
    python3 tools/scan_agm_edge.py 3000 2.5     # 1.47e-15
    python3 tools/scan_agm_edge.py 12000 4      # 1.38e-15
"""
import math
import subprocess
import sys

import mpmath as mp

mp.mp.dps = 40


def main():
    n, decades = int(sys.argv[1]), float(sys.argv[2])
    ms = [1.0 - math.ceil(10 ** (-12 + decades * i / (n - 1)) * 2**53) / 2**53 for i in range(n)]
    text = "m\n" + "".join(repr(m) + "\n" for m in ms)
    cmd = ["target/release/contact_eval", "elliptic", "--method", "agm"]
    out = subprocess.run(cmd, input=text, capture_output=True, text=True, check=True).stdout
    worst_k = worst_e = 0.0
    at = None
    for line in out.splitlines()[1:]:
        m, k, e = map(float, line.split(","))
        ek = abs((k - mp.ellipk(m)) / mp.ellipk(m))
        ee = abs((e - mp.ellipe(m)) / mp.ellipe(m))
        worst_k = max(worst_k, float(ek))
        if ee > worst_e:
            worst_e, at = float(ee), 1 - m
    print(f"K {worst_k:.2e}, E {worst_e:.2e} at m1 = {at:.3e} ({n} points)")


if __name__ == "__main__":
    main()
