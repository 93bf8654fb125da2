"""kdpm.GeometryFile: zero-copy sections, batched rays against a brute-force reference, bad input."""
import gc
import shutil

import numpy as np
import pytest

import kdpm
from reference_math import brute_force_hits


def random_rays(g, n, seed):
    """Rays from random points inside the scene's bounds in random directions (incoherent)."""
    rng = np.random.default_rng(seed)
    lo, hi = np.array(g.info["bounds_min"]), np.array(g.info["bounds_max"])
    origins = (lo + (hi - lo) * rng.uniform(0.02, 0.98, (n, 3))).astype(np.float32)
    directions = rng.normal(size=(n, 3)).astype(np.float32)
    return origins, directions


def check_against_brute_force(g, origins, directions):
    tri = g.triangles
    hits = g.intersect(origins, directions)
    t_ref, tri_ref, second = brute_force_hits(tri["v0"], tri["e1"], tri["e2"], origins, directions)
    found, found_ref = hits["triangle"] >= 0, tri_ref >= 0
    # Rays within float32 rounding of a triangle's edge may go either way.
    with np.errstate(invalid="ignore"):
        clear = np.isinf(t_ref) | (np.abs(second - t_ref) > 1e-4 * np.maximum(t_ref, 1))
    assert np.mean(found == found_ref) > 0.999
    both = found & found_ref
    np.testing.assert_allclose(hits["t"][both], t_ref[both], rtol=1e-4, atol=1e-5)
    same = both & clear
    assert np.mean(hits["triangle"][same] == tri_ref[same]) > 0.999
    assert np.all(np.isinf(hits["t"][~found]))
    assert np.all(hits["material"][~found] == -1) and np.all(hits["material"][found] >= 0)
    return hits


def test_random_rays_hit_what_brute_force_hits(geometry):
    origins, directions = random_rays(geometry, 4000, seed=1)
    hits = check_against_brute_force(geometry, origins, directions)
    assert np.mean(hits["triangle"] >= 0) > 0.6  # inside a box open at the front most rays hit


def test_camera_rays_hit_what_brute_force_hits(geometry):
    origins, directions = geometry.camera_rays(48, 48)
    hits = check_against_brute_force(geometry, origins, directions)
    found = hits["triangle"] >= 0
    # The hit point lies on its triangle: v0 + u e1 + v e2 == origin + t d.
    tri = geometry.triangles[hits["triangle"][found]]
    on_triangle = tri["v0"] + hits["u"][found, None] * tri["e1"] + hits["v"][found, None] * tri["e2"]
    along_ray = origins[found] + hits["t"][found, None] * directions[found]
    np.testing.assert_allclose(on_triangle, along_ray, atol=1e-4)


def test_normals_are_unit_and_geometric_without_vertex_normals(geometry):
    origins, directions = random_rays(geometry, 500, seed=2)
    hits = geometry.intersect(origins, directions)
    found = hits["triangle"] >= 0
    n = hits["normal"][found]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-5)
    tri = geometry.triangles[hits["triangle"][found]]
    has_normals = (tri["flags"] & 1) != 0
    geometric = np.cross(tri["e1"], tri["e2"])
    geometric /= np.linalg.norm(geometric, axis=1)[:, None]
    np.testing.assert_allclose(n[~has_normals], geometric[~has_normals], atol=1e-5)
    assert np.all(hits["normal"][~found] == 0)


def test_tmax_and_occluded_agree_with_the_closest_hit(geometry):
    origins, directions = random_rays(geometry, 2000, seed=3)
    t = geometry.intersect(origins, directions)["t"]
    tmax = np.where(np.isfinite(t), t, 1.0) * np.random.default_rng(4).uniform(0.5, 1.5, len(t))
    tmax = tmax.astype(np.float32)
    clear = np.abs(tmax - t) > 1e-3 * np.maximum(t, 1)
    limited = geometry.intersect(origins, directions, tmax=tmax)
    expected_hit = t < tmax
    assert np.all((limited["triangle"] >= 0)[clear] == expected_hit[clear])
    occluded = geometry.occluded(origins, directions, tmax=tmax)
    assert occluded.dtype == np.bool_
    assert np.all(occluded[clear] == expected_hit[clear])
    assert np.all(geometry.occluded(origins, directions, tmax=0.0) == False)  # noqa: E712


def test_float64_rays_give_the_float32_hits(geometry):
    origins, directions = random_rays(geometry, 300, seed=5)
    a = geometry.intersect(origins, directions)
    b = geometry.intersect(origins.astype(np.float64), directions.astype(np.float64))
    assert np.array_equal(a["triangle"], b["triangle"]) and np.array_equal(a["t"], b["t"])


def test_sections_are_read_only_views_of_the_mapping(cornell):
    g = kdpm.GeometryFile(cornell["kdg"])
    triangles = g.triangles
    assert triangles.base is g or triangles.base.base is g
    assert not triangles.flags.writeable and not triangles.flags.owndata
    with pytest.raises(ValueError):
        triangles["v0"][0, 0] = 1.0
    assert len(triangles) == g.info["triangle_count"] and len(g.nodes) == g.info["node_count"]
    assert g.nodes.dtype.itemsize == 8 and triangles.dtype.itemsize == 48
    assert g.materials.dtype.itemsize == 64 and g.lights.dtype.itemsize == 64
    assert np.all(triangles["material"] < len(g.materials))
    assert g.metadata["tool"] == "kdpm-build-geometry"
    before = triangles["e1"].copy()
    del g
    gc.collect()
    assert np.array_equal(triangles["e1"], before)  # the view keeps the mapping alive


@pytest.mark.parametrize(
    "origins, directions, error",
    [
        (np.zeros((4, 2), np.float32), np.ones((4, 3), np.float32), ValueError),
        (np.zeros((4, 3), np.float32), np.ones((5, 3), np.float32), ValueError),
        (np.zeros((4, 3), np.int32), np.ones((4, 3), np.float32), TypeError),
        (np.zeros((4, 3), np.complex64), np.ones((4, 3), np.float32), TypeError),
        (np.array([[0, 0, np.nan]], np.float32), np.ones((1, 3), np.float32), ValueError),
        (np.zeros((1, 3), np.float32), np.array([[np.inf, 0, 0]], np.float32), ValueError),
        (np.zeros((1, 3), np.float32), np.zeros((1, 3), np.float32), ValueError),
        ("rays", np.ones((1, 3), np.float32), TypeError),
    ],
)
def test_bad_rays_raise_cleanly(geometry, origins, directions, error):
    with pytest.raises(error):
        geometry.intersect(origins, directions)
    with pytest.raises(error):
        geometry.occluded(origins, directions)


def test_bad_tmax_raises(geometry):
    o, d = np.zeros((2, 3), np.float32), np.ones((2, 3), np.float32)
    with pytest.raises(ValueError):
        geometry.intersect(o, d, tmax=np.ones(3, np.float32))
    with pytest.raises(ValueError):
        geometry.intersect(o, d, tmax=-1.0)


def test_empty_batch(geometry):
    hits = geometry.intersect(np.zeros((0, 3), np.float32), np.zeros((0, 3), np.float32))
    assert hits["t"].shape == (0,) and hits["normal"].shape == (0, 3)


def test_bad_files_raise_format_errors(cornell, tmp_path):
    truncated = tmp_path / "truncated.kdg"
    data = cornell["kdg"].read_bytes()
    truncated.write_bytes(data[: len(data) // 2])
    with pytest.raises(kdpm.FormatError) as error:
        kdpm.GeometryFile(truncated)
    assert "\n" not in str(error.value) and str(error.value)
    flipped = tmp_path / "flipped.kdg"
    corrupt = bytearray(data)
    corrupt[len(corrupt) // 2] ^= 0x5A
    flipped.write_bytes(bytes(corrupt))
    with pytest.raises(kdpm.FormatError):
        kdpm.GeometryFile(flipped)
    with pytest.raises(kdpm.FormatError):
        kdpm.GeometryFile(tmp_path / "missing.kdg")
    with pytest.raises(kdpm.FormatError):
        kdpm.GeometryFile(cornell["kdp"])  # a photon map is not a geometry file
    assert issubclass(kdpm.FormatError, ValueError)
    shutil.copy(cornell["kdg"], tmp_path / "copy.kdg")
    assert kdpm.GeometryFile(tmp_path / "copy.kdg").info["triangle_count"] > 0
