#!/usr/bin/python3
"""Fits the polynomial of vrlis::Atan2Lanes<float> (include/vrlis/core/lane_math.hpp):
atan(x) = x P(x^2) on [0, 1], minimising the maximum relative error (Lawson's iteratively
reweighted least squares). Prints the coefficients, highest degree first, and the error."""
import numpy as np

DEGREE = 8
x = np.concatenate([np.cos(np.linspace(0, np.pi / 2, 4000)), np.linspace(0, 1, 4000)])
x = x[x > 1e-6]
target = np.arctan(x) / x
basis = np.vstack([(x * x) ** k for k in range(DEGREE + 1)]).T
weight = np.ones_like(x)
for _ in range(200):
    w = np.sqrt(weight)
    coeffs, *_ = np.linalg.lstsq(basis * w[:, None] / target[:, None], w, rcond=None)
    weight *= np.abs(basis @ coeffs / target - 1)
    weight /= weight.sum()
xs = np.linspace(0, 1, 200001)[1:]
err = np.max(np.abs(xs * np.polyval(coeffs[::-1], xs * xs) / np.arctan(xs) - 1))
print("coefficients (highest first):", ", ".join("%.8g" % c for c in coeffs[::-1]))
print("max relative error: %.3g" % err)
