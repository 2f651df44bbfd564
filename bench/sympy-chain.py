"""bench/sympy-chain.py N -- the chain of N blocks pushed into a wall, derived by hand with SymPy.

What a person writes for the chain of bench/scale-families.lisp: for each block k, Newton's
second law along x and y (the push f on the first block, the contact force P_k between
block k and the next, P_N the wall's, the floor's normal force F_k, gravity), and the
constraints of the contacts (no vertical acceleration on the floor, equal horizontal
accelerations of touching blocks, none against the wall). SymPy solves the 4 N linear
equations; the script prints the solution. bench/bench-scale.lisp times it against
bin/ames on the same chain.
"""
import sys
import sympy

n = int(sys.argv[1]) if len(sys.argv) > 1 else 8
g, f = sympy.symbols("g f", positive=True)
m = sympy.symbols(" ".join(f"m{k}" for k in range(1, n + 1)), positive=True)
m = m if isinstance(m, tuple) else (m,)
ax = sympy.symbols(" ".join(f"ax{k}" for k in range(1, n + 1)))
ay = sympy.symbols(" ".join(f"ay{k}" for k in range(1, n + 1)))
floor = sympy.symbols(" ".join(f"F{k}" for k in range(1, n + 1)))
push = sympy.symbols(" ".join(f"P{k}" for k in range(1, n + 1)))
ax, ay, floor, push = [v if isinstance(v, tuple) else (v,) for v in (ax, ay, floor, push)]

equations = []
for k in range(n):
    before = f if k == 0 else push[k - 1]
    equations.append(sympy.Eq(m[k] * ax[k], before - push[k]))
    equations.append(sympy.Eq(m[k] * ay[k], floor[k] - m[k] * g))
    equations.append(sympy.Eq(ay[k], 0))
    equations.append(sympy.Eq(ax[k], ax[k + 1]) if k + 1 < n else sympy.Eq(ax[k], 0))

solution = sympy.solve(equations, list(ax + ay + floor + push), dict=True)
for unknown, value in sorted(solution[0].items(), key=lambda item: str(item[0])):
    print(unknown, "=", sympy.simplify(value))
