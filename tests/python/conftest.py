"""Shared fixtures: the Cornell box built through the module once per session (a small photon count)."""
import os
import pathlib

import pytest

import kdpm

SOURCE = pathlib.Path(os.environ.get("KDPM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BIN = pathlib.Path(os.environ.get("KDPM_BIN_DIR", SOURCE / "build" / "bin"))
CORNELL_CARD = SOURCE / "scenes" / "cornell-box" / "cornell-box.json"
PHOTONS = 20000


@pytest.fixture(scope="session")
def cornell(tmp_path_factory):
    """Paths of the Cornell box's .kdg, .kdph and .kdp, built by kdpm.build_geometry & co."""
    root = tmp_path_factory.mktemp("cornell")
    files = {"kdg": root / "cornell.kdg", "kdph": root / "cornell.kdph", "kdp": root / "cornell.kdp"}
    kdpm.build_geometry(CORNELL_CARD, files["kdg"], quiet=True)
    kdpm.shoot_photons(files["kdg"], files["kdph"], photons=PHOTONS, quiet=True)
    kdpm.build_photons(files["kdph"], files["kdp"], quiet=True)
    return files


@pytest.fixture(scope="session")
def geometry(cornell):
    return kdpm.GeometryFile(cornell["kdg"])


@pytest.fixture(scope="session")
def photons(cornell):
    return kdpm.PhotonMapFile(cornell["kdp"])
