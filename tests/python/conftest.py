"""Shared helpers of the geomquery tests: small meshes and brute-force answers in numpy."""

import os

import numpy as np
import pytest


def shared_dir():
    """The shared data folder: $GQ_SHARED_DIR, else ../shared beside the repository."""
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("GQ_SHARED_DIR") or os.path.normpath(os.path.join(here, "..", "..", "..", "shared"))


def require_shared(*parts):
    path = os.path.join(shared_dir(), *parts)
    if not os.path.exists(path):
        pytest.skip("the shared data folder does not hold %s" % path)
    return path


def cube_mesh(half=1.0):
    """A closed cube of 12 outward-facing triangles."""
    v = np.array([[x, y, z] for x in (-half, half) for y in (-half, half) for z in (-half, half)], dtype=np.float64)
    f = np.array([
        [0, 1, 3], [0, 3, 2],  # -x
        [4, 6, 7], [4, 7, 5],  # +x
        [0, 4, 5], [0, 5, 1],  # -y
        [2, 3, 7], [2, 7, 6],  # +y
        [0, 2, 6], [0, 6, 4],  # -z
        [1, 5, 7], [1, 7, 3],  # +z
    ], dtype=np.int64)
    return v, f


def icosphere(subdivisions=1):
    """A closed sphere-like mesh, outward faces."""
    t = (1.0 + 5 ** 0.5) / 2.0
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    v = [np.array(p, dtype=np.float64) / np.linalg.norm(p) for p in v]
    for _ in range(subdivisions):
        cache, nf = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = v[a] + v[b]
                v.append(m / np.linalg.norm(m))
                cache[key] = len(v) - 1
            return cache[key]

        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        f = nf
    return np.array(v), np.array(f, dtype=np.int64)


def brute_rays(vertices, faces, origins, directions):
    """Every (ray, triangle, distance) hit of half-lines against triangles (Moller-Trumbore, both sides)."""
    tri = vertices[faces]
    e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    hits = []
    for r, (o, d) in enumerate(zip(origins, directions)):
        p = np.cross(d, e2)
        det = (e1 * p).sum(axis=1)
        ok = np.abs(det) > 1e-12
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        s = o - tri[:, 0]
        u = (s * p).sum(axis=1) * inv
        q = np.cross(s, e1)
        w = (q * d).sum(axis=1) * inv
        t = (q * e2).sum(axis=1) * inv
        good = ok & (u >= 0) & (w >= 0) & (u + w <= 1) & (t >= 0)
        for i in np.nonzero(good)[0]:
            hits.append((r, int(i), float(t[i])))
    return hits


def brute_point_distance(vertices, faces, p):
    """Distance from p to the closest triangle, by dense sampling refined with exact edge/face projections."""
    best = np.inf
    for a, b, c in vertices[faces]:
        best = min(best, point_triangle_distance(p, a, b, c))
    return best


def point_triangle_distance(p, a, b, c):
    n = np.cross(b - a, c - a)
    n = n / np.linalg.norm(n)
    proj = p - np.dot(p - a, n) * n
    # Inside test with barycentric coordinates.
    v0, v1, v2 = b - a, c - a, proj - a
    d00, d01, d11 = v0 @ v0, v0 @ v1, v1 @ v1
    d20, d21 = v2 @ v0, v2 @ v1
    den = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / den
    w = (d00 * d21 - d01 * d20) / den
    if v >= 0 and w >= 0 and v + w <= 1:
        return abs(np.dot(p - a, n))

    def seg(p, x, y):
        t = np.clip(np.dot(p - x, y - x) / np.dot(y - x, y - x), 0, 1)
        return np.linalg.norm(p - (x + t * (y - x)))

    return min(seg(p, a, b), seg(p, b, c), seg(p, c, a))
