"""Polynomials in joint angles: p(q) = sum_k c_k prod_j q_j^e_kj, stored as (exponents, coefs)."""
from __future__ import annotations

import numpy as np


def evaluate(exponents, coefs, q):
    """Value of the polynomial at poses q (N, ndof) -> (N,)."""
    e = np.asarray(exponents, dtype=int).reshape(len(coefs), -1)
    q = np.atleast_2d(np.asarray(q, dtype=float))
    terms = np.prod(q[:, None, :] ** e[None, :, :], axis=2)
    return terms @ np.asarray(coefs, dtype=float)


def gradient(exponents, coefs, q):
    """d p / d q at poses q (N, ndof) -> (N, ndof)."""
    e = np.asarray(exponents, dtype=int).reshape(len(coefs), -1)
    c = np.asarray(coefs, dtype=float)
    q = np.atleast_2d(np.asarray(q, dtype=float))
    out = np.zeros_like(q)
    for j in range(e.shape[1]):
        ej = e[:, j]
        reduced = e.copy()
        reduced[:, j] = np.maximum(ej - 1, 0)
        terms = np.prod(q[:, None, :] ** reduced[None, :, :], axis=2)
        out[:, j] = terms @ (c * ej)
    return out


def substitute(exponents, coefs, fixed: dict[int, float]):
    """Substitute fixed values for some variables and merge equal monomials.

    Returns (kept_variable_indices, exponents over the kept variables, coefs). Terms that cancel to
    exactly zero are dropped; the order of the remaining monomials is the order of first appearance,
    so the result is deterministic.
    """
    e = np.asarray(exponents, dtype=int).reshape(len(coefs), -1)
    kept = [j for j in range(e.shape[1]) if j not in fixed]
    merged: dict[tuple, float] = {}
    for row, c in zip(e, np.asarray(coefs, dtype=float)):
        factor = c
        for j, value in fixed.items():
            factor *= value ** int(row[j])
        key = tuple(int(row[j]) for j in kept)
        merged[key] = merged.get(key, 0.0) + factor
    items = [(k, v) for k, v in merged.items() if v != 0.0]
    exps = [list(k) for k, _ in items]
    cs = [v for _, v in items]
    return kept, exps, cs
