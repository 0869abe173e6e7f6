# Step 4 of the recovery (docs/textures.md): finds the permutation P of the course's
# lattice from the recovered gradients Gamma(i, j, k) (gamma.npy, from analyze.py).
# Model: Gamma(i, j, k) = G[P[(i + A(j, k)) mod 16]], A(j, k) = P[(j + P[k]) mod 16].
# For fixed (j, k) the gradients along i are a cyclic shift of one 16-periodic sequence;
# for fixed k the shifts along j are a cyclic shift of P (plus a constant).
import collections
import numpy as np

def align(rows):
    """rows: {key: {index: value}}. Finds a 16-periodic sequence Q and a shift per row with
    row[i] = Q[(i + shift) % 16], growing from the longest row; rows whose shift is not
    unique are left out."""
    order = sorted(rows, key=lambda r: -len(rows[r]))
    Q, shift = {}, {order[0]: 0}
    for i, v in rows[order[0]].items():
        Q[i % 16] = v
    changed = True
    while changed:
        changed = False
        for r in order:
            if r in shift:
                continue
            cands = [s for s in range(16)
                     if all(Q.get((i + s) % 16, v) == v for i, v in rows[r].items())
                     and sum((i + s) % 16 in Q for i in rows[r]) >= 3]
            if len(cands) == 1:
                shift[r] = cands[0]
                for i, v in rows[r].items():
                    Q[(i + cands[0]) % 16] = v
                changed = True
    return Q, shift

g = np.load('/tmp/perlin/gamma.npy')
rows = collections.defaultdict(dict)
for i, j, k, v in g:
    rows[(j, k)][i] = v
Q, shift = align(rows)
by_k = collections.defaultdict(dict)
for (j, k), s in shift.items():
    by_k[k][j] = s
S, t = align(by_k)
print('Q (gradient ids along i):', [Q.get(m) for m in range(16)])
print('S (shifts along j):', [S.get(m) for m in range(16)])
G16 = [(1, 1, 0), (-1, 1, 0), (1, -1, 0), (-1, -1, 0), (1, 0, 1), (-1, 0, 1), (1, 0, -1),
       (-1, 0, -1), (0, 1, 1), (0, -1, 1), (0, 1, -1), (0, -1, -1), (1, 1, 0), (-1, 1, 0),
       (0, -1, 1), (0, -1, -1)]
# shift(j, k) = A(j, k) + c = P[(j + P[k]) % 16] + c and S[(j + t(k)) % 16] = shift(j, k):
# P[m] = S[(m + e) % 16] - c with P[k] = t(k) - e.
for c in range(16):
    for e in range(16):
        if any(S.get(m) is None for m in range(16)):
            continue
        P = [(S[(m + e) % 16] - c) % 16 for m in range(16)]
        if all(P[k % 16] == (t[k] - e) % 16 for k in t) and \
           all(Q.get(m) is None or G16[Q[m]] == G16[P[(m - c) % 16]] for m in range(16)):
            print('P =', P)
