"""The jobs and the render from Python: the same files and images as the tools, the same output
discipline, analytic hits on a mesh given as arrays."""
import subprocess

import numpy as np
import pytest

import kdpm
from conftest import BIN, CORNELL_CARD, PHOTONS


def run_tool(*args):
    subprocess.run([str(BIN / args[0]), *map(str, args[1:]), "--quiet"], check=True)


def read_pfm(path):
    """A colour PFM as an (H, W, 3) float32 array, row 0 at the top."""
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3)[::-1]


def test_module_files_are_the_tools_files_byte_for_byte(cornell, tmp_path):
    run_tool("kdpm-build-geometry", CORNELL_CARD, "-o", tmp_path / "cornell.kdg")
    run_tool("kdpm-shoot-photons", tmp_path / "cornell.kdg", "-o", tmp_path / "cornell.kdph", "-n", PHOTONS)
    run_tool("kdpm-build-photons", tmp_path / "cornell.kdph", "-o", tmp_path / "cornell.kdp")
    for kind in ("kdg", "kdph", "kdp"):
        assert (tmp_path / f"cornell.{kind}").read_bytes() == cornell[kind].read_bytes(), kind


def test_render_is_kdpm_render_s_image(cornell, geometry, photons, tmp_path):
    for mode in ("photons", "direct", "final-gather"):
        out = tmp_path / f"{mode}.pfm"
        run_tool("kdpm-render", cornell["kdg"], cornell["kdp"], "-o", out, "--mode", mode, "--width", 40,
                 "--height", 30, "--spp", 2, "--backend", "cpu")
        image = kdpm.render(geometry, photons, mode=mode, width=40, height=30, spp=2, quiet=True)
        assert image.shape == (30, 40, 3) and image.dtype == np.float32
        assert np.array_equal(image, read_pfm(out)), mode
        assert np.all(np.isfinite(image)) and image.mean() > 0
    # The path-traced gather lookup, through both doors.
    out = tmp_path / "fg-path.pfm"
    run_tool("kdpm-render", cornell["kdg"], cornell["kdp"], "-o", out, "--mode", "final-gather", "--width", 24,
             "--height", 16, "--gather-rays", 8, "--gather-lookup", "path", "--backend", "cpu")
    image = kdpm.render(geometry, photons, mode="final-gather", width=24, height=16, gather_rays=8,
                        gather_lookup="path", quiet=True)
    assert np.array_equal(image, read_pfm(out))


def test_render_aovs_match_the_rays(geometry):
    out = kdpm.render(geometry, mode="direct", width=24, height=24, aovs=["depth", "triangle", "normal"], quiet=True)
    assert set(out) == {"color", "depth", "triangle", "normal"}
    assert out["depth"].shape == (24, 24) and out["normal"].shape == (24, 24, 3)
    hit = out["triangle"] >= 0
    assert np.all(np.isfinite(out["depth"][hit])) and np.all(np.isinf(out["depth"][~hit]))
    np.testing.assert_allclose(np.linalg.norm(out["normal"][hit], axis=-1), 1.0, atol=1e-4)


def test_camera_rays_are_the_renderer_s(geometry):
    camera = {"eye": [0.2, 1.1, 3.5], "lookat": [0, 0.9, 0], "vfov": 45}
    out = kdpm.render(geometry, mode="albedo", width=20, height=16, aovs=["depth", "triangle"], camera=camera,
                      quiet=True)
    origins, directions = geometry.camera_rays(20, 16, camera=camera)
    assert origins.shape == (320, 3)
    np.testing.assert_allclose(np.linalg.norm(directions, axis=1), 1.0, rtol=1e-6)
    hits = geometry.intersect(origins, directions)
    assert np.array_equal(hits["triangle"] >= 0, out["triangle"].reshape(-1) >= 0)
    found = hits["triangle"] >= 0
    np.testing.assert_allclose(hits["t"][found], out["depth"].reshape(-1)[found], rtol=1e-5)
    tri = geometry.triangles["source_index"][hits["triangle"][found]]
    assert np.array_equal(tri, out["triangle"].reshape(-1)[found])


def test_render_refuses_what_kdpm_render_refuses(geometry):
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="photons")  # no photon map
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="nonsense")
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="direct", gather_lookup="nearest")
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="direct", spp=0)
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="direct", passes=4)
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="direct", camera={"eye": [0, 1, 0], "lookat": [0, 1, 0]})
    with pytest.raises(ValueError):
        kdpm.render(geometry, mode="direct", aovs=["albedo"])


def test_mesh_from_arrays_gives_analytic_hits(tmp_path):
    # A unit square in the plane z = 2 as two triangles.
    vertices = np.array([[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]], np.float32)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    stats = kdpm.build_geometry((vertices, faces), tmp_path / "square.kdg", quiet=True)
    assert stats["triangles"] == 2 and stats["nodes"] >= 1
    g = kdpm.GeometryFile(tmp_path / "square.kdg")
    rng = np.random.default_rng(3)
    xy = rng.uniform(-0.5, 1.5, (1000, 2)).astype(np.float32)
    origins = np.column_stack([xy, np.zeros(1000, np.float32)])
    directions = np.tile(np.array([[0, 0, 1]], np.float32), (1000, 1))
    hits = g.intersect(origins, directions)
    inside = np.all((xy > 1e-4) & (xy < 1 - 1e-4), axis=1)
    outside = np.any((xy < -1e-4) | (xy > 1 + 1e-4), axis=1)
    assert np.all(hits["triangle"][inside] >= 0) and np.all(hits["triangle"][outside] == -1)
    np.testing.assert_allclose(hits["t"][inside], 2.0, rtol=1e-6)
    np.testing.assert_allclose(np.abs(hits["normal"][inside][:, 2]), 1.0)


@pytest.mark.parametrize(
    "faces, error",
    [
        (np.array([[0, 1, 4]]), ValueError),
        (np.array([[0, 1, -1]]), ValueError),
        (np.array([[0, 1]]), ValueError),
        (np.array([[0.0, 1.0, 2.0]]), TypeError),
        (np.zeros((0, 3), np.int32), ValueError),
    ],
)
def test_bad_meshes_raise_and_write_nothing(tmp_path, faces, error):
    vertices = np.eye(3, dtype=np.float32)
    with pytest.raises(error):
        kdpm.build_geometry((vertices, faces), tmp_path / "bad.kdg", quiet=True)
    assert not (tmp_path / "bad.kdg").exists()


def test_jobs_keep_the_output_discipline(cornell, tmp_path):
    with pytest.raises(ValueError):  # the output is the input
        kdpm.build_photons(cornell["kdph"], cornell["kdph"], quiet=True)
    with pytest.raises(Exception):
        kdpm.build_geometry(CORNELL_CARD, tmp_path / "no" / "such" / "dir" / "x.kdg", quiet=True)
    # A failing job leaves an existing output as it was.
    existing = tmp_path / "existing.kdp"
    existing.write_bytes(b"keep me")
    bad = tmp_path / "bad.kdph"
    bad.write_bytes(cornell["kdph"].read_bytes()[:100])
    with pytest.raises(kdpm.FormatError):
        kdpm.build_photons(bad, existing, quiet=True)
    assert existing.read_bytes() == b"keep me"
    with pytest.raises(ValueError):
        kdpm.shoot_photons(cornell["kdg"], tmp_path / "x.kdph", photons=-5, quiet=True)
    with pytest.raises(ValueError):
        kdpm.build_photons(cornell["kdph"], tmp_path / "x.kdp", irradiance_k=0, quiet=True)
    with pytest.raises(ValueError):
        kdpm.build_geometry(CORNELL_CARD, tmp_path / "x.kdg", quality="best", quiet=True)


def test_shards_refused_like_the_tool(cornell, tmp_path):
    result = kdpm.shoot_photons(cornell["kdg"], tmp_path / "half.kdph", photons=2000, paths="0:1000", quiet=True)
    assert result["paths"] == (0, 1000) and result["emitted"] == 2000
    with pytest.raises(ValueError, match="shard"):
        kdpm.build_photons(tmp_path / "half.kdph", tmp_path / "half.kdp", quiet=True)
