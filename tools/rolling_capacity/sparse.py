"""Greedy sparse subsets (fit_rolling_reach.sparse_select, selection on all training rows) of a variant's design:
sparse.py EXTRA REL K [K ...]  (EXTRA '-' for none, REL '-' for none)."""
import sys; sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__))); import numpy as np
ex = sys.argv[1].split(',') if sys.argv[1] != '-' else []
rel = int(sys.argv[2]) if sys.argv[2] != '-' else None
ks = [int(k) for k in sys.argv[3:] if '=' not in k]
sys.argv = ['x', 'x'] + [a for a in sys.argv if a.startswith(('lawson=', 'lam='))]
import cap
import fit_rolling_reach as R
tr, ho = cap.load()
bt, bh = cap.poly_blocks(tr, ex, 3, rel=rel), cap.poly_blocks(ho, ex, 3, rel=rel)
a = np.concatenate([bt(lo, lo + 4000) for lo in range(0, len(tr['aob']), 4000)])
ah = bh(0, len(ho['aob']))
res = tr['ref'] - tr['base']
sc = np.maximum(np.sqrt((a * a).mean(0)), 1e-12)
sel_all = R.sparse_select(a / sc, res, max(ks), 1e-4)
for k in ks:
    sel = sel_all[:k]
    o = cap.evaluate(tr, ho, lambda lo, hi: a[lo:hi][:, sel], lambda lo, hi: ah[lo:hi][:, sel],
                     name=f"{','.join(ex) or 'log'} rel{rel} sparse {k}")
    cap.report(o, cap.OUT / "sparse.md")
