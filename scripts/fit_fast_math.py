#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Coefficients of lod/fast_math.hpp's polynomials, and their worst error.

Each polynomial interpolates its function at the Chebyshev nodes of the reduced range, which
is within a small factor of the minimax polynomial of the same degree (no numpy needed).
  atan:  atan u = u + u^3 Q(u^2),   Q on x = u^2 in [0, tan^2(pi/8)]
  log10: ln m = 2 y S(y^2),          S on z = y^2 in [0, ((sqrt2 - 1) / (sqrt2 + 1))^2]
Usage: python3 scripts/fit_fast_math.py   (prints degree, worst error, coefficients)
"""
import math


def solve(a, b):
    """Gaussian elimination with partial pivoting (small dense systems)."""
    n = len(a)
    m = [row[:] + [bb] for row, bb in zip(a, b)]
    for i in range(n):
        p = max(range(i, n), key=lambda r: abs(m[r][i]))
        m[i], m[p] = m[p], m[i]
        for r in range(n):
            if r != i:
                f = m[r][i] / m[i][i]
                for c in range(i, n + 1):
                    m[r][c] -= f * m[i][c]
    return [m[i][n] / m[i][i] for i in range(n)]


def chebyshev_fit(fn, top, degree):
    n = degree + 1
    xs = [top / 2 * (1 - math.cos((2 * i + 1) * math.pi / (2 * n))) for i in range(n)]
    return solve([[x ** j for j in range(n)] for x in xs], [fn(x) for x in xs])


def poly(c, x):
    return sum(cj * x ** j for j, cj in enumerate(c))


def q_atan(x):  # (atan u - u) / u^3 by its series (x <= 0.17: converges fast)
    return sum((-1) ** k * x ** (k - 1) / (2 * k + 1) for k in range(1, 60))


def s_log(z):  # atanh(y) / y by its series
    return sum(z ** k / (2 * k + 1) for k in range(40))


def main():
    x_top = math.tan(math.pi / 8) ** 2
    print("atan_small: degree, max |atan error| (rad), coefficients of Q")
    for deg in range(3, 8):
        c = chebyshev_fit(q_atan, x_top, deg)
        worst = 0.0
        for i in range(4001):
            u = math.sqrt(x_top * i / 4000)
            worst = max(worst, abs(u + u * u * u * poly(c, u * u) - math.atan(u)))
        print(deg, "%.2e" % worst, ["%.17g" % v for v in c])
    z_top = ((math.sqrt(2) - 1) / (math.sqrt(2) + 1)) ** 2
    print("log10_normal: degree, max |log10 error|, coefficients of S")
    for deg in range(2, 7):
        c = chebyshev_fit(s_log, z_top, deg)
        worst = 0.0
        for i in range(20001):
            m = math.sqrt(0.5) + (math.sqrt(2) - math.sqrt(0.5)) * i / 20000
            y = (m - 1) / (m + 1)
            worst = max(worst, abs(2 * y * poly(c, y * y) - math.log(m)) / math.log(10))
        print(deg, "%.2e" % worst, ["%.17g" % v for v in c])


if __name__ == "__main__":
    main()
