#!/usr/bin/env python3
"""kdpm-bench for the Python module: what Python adds to a batch of rays, and k-nearest queries
against SciPy's cKDTree, on the Sponza, both sides measured in this run.

    PYTHONPATH=build/python python3 tools/bench/bench_python.py [--repeats N] [--keep DIR]

Needs ../shared/scenes (or $KDPM_SCENES); prints a clear message and exits 0 without it.
Targets (issue 55): a batch from Python within 1.1x of the same batch through the C++ loop;
knn k=32 at the primary hits at most 0.5x cKDTree.query(workers=-1), with the same neighbours.
"""
import argparse
import os
import pathlib
import statistics
import sys
import tempfile
import time

import numpy as np
from scipy.spatial import cKDTree

import kdpm

SOURCE = pathlib.Path(__file__).resolve().parents[2]
CARD = SOURCE / "scenes" / "sponza" / "sponza.json"
K = 32


def bounce_rays(points, normals, seed=1):
    """Cosine-distributed diffuse bounce rays from the hits: incoherent, as photon paths trace."""
    rng = np.random.default_rng(seed)
    r1, r2 = rng.random(len(points)), rng.random(len(points))
    phi, s = 2 * np.pi * r1, np.sqrt(r2)
    local = np.column_stack([s * np.cos(phi), s * np.sin(phi), np.sqrt(1 - r2)])
    n = normals.astype(np.float64)
    helper = np.where(np.abs(n[:, :1]) > 0.9, [[0, 1, 0]], [[1, 0, 0]])
    t = np.cross(n, helper)
    t /= np.linalg.norm(t, axis=1)[:, None]
    b = np.cross(n, t)
    d = local[:, :1] * t + local[:, 1:2] * b + local[:, 2:] * n
    return (points + 1e-3 * normals).astype(np.float32), d.astype(np.float32)


def timed(call, repeats):
    seconds = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds), result


def ray_row(name, g, origins, directions, repeats):
    # Interleaved, so that a noisy moment of the shared machine hits both sides alike.
    py, cpp = [], []
    for _ in range(repeats):
        py.append(timed(lambda: g.intersect(origins, directions), 1)[0])
        cpp.extend(g._cpp_intersect_seconds(origins, directions, 1))
    p, c = statistics.median(py), statistics.median(cpp)
    rays = len(origins)
    print(f"  {name:<8} {rays:>8} rays   Python {p * 1e3:8.1f} ms   C++ {c * 1e3:8.1f} ms   "
          f"{rays / p * 1e-6:6.2f} M rays/s   Python / C++ {p / c:5.3f}x")
    return p / c


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7, help="runs of each timed call; the median counts")
    parser.add_argument("--keep", help="build the Sponza's files into this folder and keep them")
    args = parser.parse_args()
    if args.repeats < 1:
        parser.error("--repeats must be at least 1")
    scenes = os.environ.get("KDPM_SCENES", str(SOURCE.parent / "shared" / "scenes"))
    if not (pathlib.Path(scenes) / "sponza" / "sponza.obj").exists():
        print(f"bench_python: skipped: no Sponza under {scenes} (set KDPM_SCENES to a folder with sponza/sponza.obj)")
        return 0

    with tempfile.TemporaryDirectory() as temp:
        folder = pathlib.Path(args.keep or temp)
        folder.mkdir(parents=True, exist_ok=True)
        kdg, kdph, kdp = (folder / f"sponza.{e}" for e in ("kdg", "kdph", "kdp"))
        for path in (kdg, kdph, kdp):
            path.unlink(missing_ok=True)
        kdpm.build_geometry(CARD, kdg)
        kdpm.shoot_photons(kdg, kdph)
        kdpm.build_photons(kdph, kdp)
        g, p = kdpm.GeometryFile(kdg), kdpm.PhotonMapFile(kdp)
        print(f"bench_python: Sponza, {g.info['triangle_count']} triangles, {p.photon_count} photons "
              f"({p.emitted_count} paths), kdpm {kdpm.__version__}, {os.cpu_count()} cores, median of "
              f"{args.repeats}")

        print("rays: GeometryFile.intersect vs the same batch through the C++ loop (closest_hit on every thread)")
        origins, directions = g.camera_rays()
        primary = g.intersect(origins, directions)
        found = primary["triangle"] >= 0
        points = origins[found] + primary["t"][found, None] * directions[found]
        normals = primary["normal"][found]
        facing = np.where(np.sum(normals * directions[found], axis=1)[:, None] > 0, -normals, normals)
        ratio_primary = ray_row("primary", g, origins, directions, args.repeats)
        ratio_bounce = ray_row("bounce", g, *bounce_rays(points, facing), args.repeats)

        print(f"knn: k = {K} at the {len(points)} primary hits, PhotonMapFile.knn vs cKDTree.query(workers=-1)")
        positions = p.positions()
        build_start = time.perf_counter()
        tree = cKDTree(positions)
        build = time.perf_counter() - build_start
        kd_time, (d, i) = timed(lambda: p.knn(points, K), args.repeats)
        sp_time, _ = timed(lambda: tree.query(points, K, workers=-1), args.repeats)
        d_ref, i_ref = tree.query(points, K + 1, workers=-1)  # one more, to tell ties at the K-th apart
        clear = d_ref[:, K] - d_ref[:, K - 1] > 1e-5 * (1 + d_ref[:, K])
        same = np.all(np.sort(i, axis=1) == np.sort(i_ref[:, :K], axis=1), axis=1)
        print(f"  kdpm {kd_time * 1e3:8.1f} ms   SciPy {sp_time * 1e3:8.1f} ms (its tree built in "
              f"{build * 1e3:.0f} ms, not counted)   kdpm / SciPy {kd_time / sp_time:5.3f}x")
        print(f"  same {K} neighbours at {np.mean(same[clear]) * 100:.3f} % of the {clear.sum()} queries whose "
              f"{K}th and {K + 1}th photons are apart ({np.mean(same) * 100:.3f} % of all); largest distance "
              f"difference {np.max(np.abs(d - d_ref[:, :K])):.2e}")

    def verdict(ok):
        return "met" if ok else "MISSED"

    print(f"targets: rays within 1.1x of C++: {verdict(max(ratio_primary, ratio_bounce) <= 1.1)}; "
          f"knn <= 0.5x SciPy: {verdict(kd_time / sp_time <= 0.5)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
