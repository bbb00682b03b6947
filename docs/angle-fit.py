#!/usr/bin/env python3
"""The polynomial of src/geometry/angle.rs, in exact arithmetic (standard library only).

g(z) = (atan(sqrt z)/sqrt z - 1)/z = sum_{k>=1} (-1)^k z^(k-1)/(2k+1) on 0 <= z <= tan^2(pi/8):
its Taylor series to 60 terms (remainder below 1e-45 there), rewritten in Chebyshev
polynomials of the interval, cut at degree 10 and turned back into powers of z. Prints, per
degree, the bound on the truncation's error in atan(u) relative to u (zmax times the sum of
the dropped Chebyshev coefficients), and the coefficients of degree 10 rounded to f64.
"""
from fractions import Fraction as F

ZMAX = F(17157287525381, 10**14)  # tan^2(pi/8) = 3 - 2 sqrt 2 = 0.1715728752538099..., rounded up
TERMS = 60
DEGREE = 10


def mul(a, b):
    r = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def compose(coefficients, linear):
    """sum c_k (linear)^k as a power series."""
    out, power = [F(0)], [F(1)]
    for c in coefficients:
        out = [(out[i] if i < len(out) else 0) + c * (power[i] if i < len(power) else 0)
               for i in range(max(len(out), len(power)))]
        power = mul(power, linear)
    return out


def chebyshev(n):
    t = [[F(1)], [F(0), F(1)]]
    for k in range(2, n):
        a = [F(0)] + [2 * x for x in t[k - 1]]
        t.append([x - (t[k - 2][i] if i < len(t[k - 2]) else 0) for i, x in enumerate(a)])
    return t


def main():
    h = ZMAX / 2
    taylor = [F((-1) ** k, 2 * k + 1) for k in range(1, TERMS + 1)]
    in_s = compose(taylor, [h, h])  # z = h (1 + s), s in [-1, 1]
    t = chebyshev(len(in_s))
    cheb, rest = [F(0)] * len(in_s), in_s[:]
    for k in range(len(in_s) - 1, -1, -1):
        cheb[k] = rest[k] / t[k][k]
        for i, x in enumerate(t[k]):
            rest[i] -= cheb[k] * x
    for degree in range(6, 14):
        print(f"degree {degree}: truncation {float(ZMAX * sum(abs(c) for c in cheb[degree + 1:])):.1e}")
    kept = [F(0)] * len(in_s)
    for k in range(DEGREE + 1):
        for i, x in enumerate(t[k]):
            kept[i] += cheb[k] * x
    in_z = compose(kept[:DEGREE + 1], [F(-1), 1 / h])  # s = z/h - 1
    print("coefficients, lowest power first:")
    for c in in_z:
        print(f"    {float(c)!r},")


if __name__ == "__main__":
    main()
