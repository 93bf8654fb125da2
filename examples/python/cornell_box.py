#!/usr/bin/env python3
"""Builds the shipped Cornell box from Python, renders it, and plots the render, the photon
density on the visible surfaces and the depth map with matplotlib.

    PYTHONPATH=build/python python3 examples/python/cornell_box.py [OUT_DIR]

writes OUT_DIR/cornell-box.{kdg,kdph,kdp} and OUT_DIR/cornell-box-plots.png (default out/python).
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import kdpm  # noqa: E402

SOURCE = pathlib.Path(__file__).resolve().parents[2]
CARD = SOURCE / "scenes" / "cornell-box" / "cornell-box.json"
K = 32


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python")
    out.mkdir(parents=True, exist_ok=True)
    kdg, kdph, kdp = (out / f"cornell-box.{ext}" for ext in ("kdg", "kdph", "kdp"))

    built = kdpm.build_geometry(CARD, kdg)
    shot = kdpm.shoot_photons(kdg, kdph)
    kdpm.build_photons(kdph, kdp)
    geometry, photons = kdpm.GeometryFile(kdg), kdpm.PhotonMapFile(kdp)
    print(f"{built['triangles']} triangles, {shot['stored']} photons stored from {shot['emitted']} paths")

    frame = kdpm.render(geometry, photons, mode="direct+photons", spp=4, width=256, height=256,
                        aovs=["depth", "position", "normal", "triangle"])
    color, depth, visible = frame["color"], frame["depth"], frame["triangle"] >= 0

    # Photon density (photons per square metre) where each pixel sees a surface: K / (pi r^2) for the
    # K nearest photons that may light that surface.
    distances, _ = photons.knn(frame["position"][visible], K, normals=frame["normal"][visible])
    density = np.full(depth.shape, np.nan, np.float32)
    density[visible] = K / (np.pi * distances[:, -1] ** 2)

    figure, axes = plt.subplots(1, 3, figsize=(13, 4.4), constrained_layout=True)
    axes[0].imshow(np.clip(color / (1 + color), 0, 1) ** (1 / 2.2))
    axes[0].set_title("render (direct + photons, 4 spp)")
    shown = axes[1].imshow(np.log10(density), cmap="inferno")
    figure.colorbar(shown, ax=axes[1], label="log10 photons / m$^2$")
    axes[1].set_title(f"photon density ({K} nearest, surface-filtered)")
    shown = axes[2].imshow(np.where(visible, depth, np.nan), cmap="viridis")
    figure.colorbar(shown, ax=axes[2], label="distance along the ray")
    axes[2].set_title("depth")
    for axis in axes:
        axis.set_axis_off()
    plot = out / "cornell-box-plots.png"
    figure.savefig(plot, dpi=100)
    print(f"wrote {plot}")


if __name__ == "__main__":
    main()
