"""Independent references in plain NumPy: brute-force ray/triangle hits and filtered k nearest."""
import numpy as np


def brute_force_hits(v0, e1, e2, origins, directions, tmax=np.inf):
    """Closest Möller-Trumbore hit of every ray against every triangle (float64).

    Returns (t, triangle, second_t): t = inf and triangle = -1 on a miss; second_t is the
    next-closest hit's t, to tell apart rays that graze an edge shared by two triangles."""
    o = origins.astype(np.float64)[:, None, :]
    d = directions.astype(np.float64)[:, None, :]
    v0, e1, e2 = (a.astype(np.float64)[None, :, :] for a in (v0, e1, e2))
    p = np.cross(d, e2)
    det = np.sum(e1 * p, axis=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        s = o - v0
        u = np.sum(s * p, axis=2) * inv
        q = np.cross(s, e1)
        v = np.sum(d * q, axis=2) * inv
        t = np.sum(e2 * q, axis=2) * inv
    ok = (np.abs(det) > 1e-12) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < tmax)
    t = np.where(ok, t, np.inf)
    order = np.argsort(t, axis=1)
    best = order[:, 0]
    rows = np.arange(len(t))
    t_best = t[rows, best]
    second = t[rows, order[:, 1]] if t.shape[1] > 1 else np.full(len(t), np.inf)
    triangle = np.where(np.isfinite(t_best), best, -1)
    return t_best, triangle, second


def filtered_knn(positions, incoming, normals, point, normal, k, min_cos=0.7):
    """The k nearest photons that arrived from the front of `normal` with a stored normal
    within min_cos of it: (distances ascending, indices)."""
    accept = (incoming @ normal < 0.0) & (normals @ normal >= min_cos)
    candidates = np.flatnonzero(accept)
    d = np.linalg.norm(positions[candidates].astype(np.float64) - point, axis=1)
    order = np.argsort(d, kind="stable")[:k]
    return d[order], candidates[order]
