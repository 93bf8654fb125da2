"""kdpm from Python: SAH geometry kd-trees, VVH photon kd-trees and photon-mapped renders.

Files open memory-mapped; their arrays are read-only NumPy views that keep the file alive::

    import kdpm
    g = kdpm.GeometryFile("scene.kdg")
    hits = g.intersect(origins, directions)          # dict: t, triangle, u, v, normal, material
    p = kdpm.PhotonMapFile("scene.kdp")
    distances, indices = p.knn(points, k=32)         # like scipy.spatial.cKDTree.query
    image = kdpm.render(g, p, mode="final-gather", spp=4)   # float32 (H, W, 3)

Every error is an exception with the tools' one-line message: kdpm.FormatError (a ValueError)
for a corrupt, truncated or foreign file, ValueError / TypeError for bad arguments.
"""
from ._kdpm import (  # noqa: F401
    FormatError,
    GeometryFile,
    PhotonMap,
    PhotonMapFile,
    __version__,
    build_geometry,
    build_photons,
    render,
    shoot_photons,
)

__all__ = [
    "FormatError",
    "GeometryFile",
    "PhotonMap",
    "PhotonMapFile",
    "build_geometry",
    "build_photons",
    "render",
    "shoot_photons",
]
