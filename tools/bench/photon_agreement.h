#pragma once
// How closely two photon shootings of the same paths agree (kdpm's shooter and a peer that
// differs only in its ray intersector): the stored counts of both maps, and path by path whether
// the same hits were stored (same bounces and flags, positions within a tolerance). Hits come in
// path order, as every shooter writes them. Float differences in a hit point can, rarely, turn a
// later bounce of that path (a grazing ray hits another triangle), so a few paths may differ.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "formats/photon_layout.h"

namespace kdpm::bench {

struct PhotonAgreement {
    std::uint64_t ours_global = 0, theirs_global = 0;    // every stored hit (the global map)
    std::uint64_t ours_caustic = 0, theirs_caustic = 0;  // those flagged caustic (the caustic map)
    std::uint64_t paths = 0;       // paths that stored a hit in either shooting
    std::uint64_t same_paths = 0;  // of those, paths whose stored hits match

    // min / max of the two counts (1 when both are 0).
    static double count_ratio(std::uint64_t a, std::uint64_t b) {
        return std::max(a, b) == 0 ? 1.0 : static_cast<double>(std::min(a, b)) / static_cast<double>(std::max(a, b));
    }
    double global_agreement() const { return count_ratio(ours_global, theirs_global); }
    double caustic_agreement() const { return count_ratio(ours_caustic, theirs_caustic); }
    double path_agreement() const { return paths == 0 ? 1.0 : static_cast<double>(same_paths) / static_cast<double>(paths); }
};

// `tolerance`: the largest coordinate difference of two positions still counted the same.
inline PhotonAgreement compare_photons(std::span<const PhotonHit> ours, std::span<const PhotonHit> theirs,
                                       float tolerance) {
    PhotonAgreement a;
    for (const PhotonHit& h : ours) a.ours_caustic += (h.flags & kPhotonCaustic) != 0;
    for (const PhotonHit& h : theirs) a.theirs_caustic += (h.flags & kPhotonCaustic) != 0;
    a.ours_global = ours.size();
    a.theirs_global = theirs.size();
    auto same_hit = [&](const PhotonHit& x, const PhotonHit& y) {
        if (x.flags != y.flags) return false;
        for (int i = 0; i < 3; ++i)
            if (!(std::fabs(x.position[i] - y.position[i]) <= tolerance)) return false;
        return true;
    };
    std::size_t i = 0, j = 0;
    while (i < ours.size() || j < theirs.size()) {
        // The next path that either side stored hits for; its run of hits on each side.
        const std::uint32_t path = j == theirs.size() || (i < ours.size() && ours[i].path <= theirs[j].path)
                                       ? ours[i].path
                                       : theirs[j].path;
        std::size_t i_end = i, j_end = j;
        while (i_end < ours.size() && ours[i_end].path == path) ++i_end;
        while (j_end < theirs.size() && theirs[j_end].path == path) ++j_end;
        bool same = i_end - i == j_end - j;
        for (std::size_t k = 0; same && k < i_end - i; ++k) same = same_hit(ours[i + k], theirs[j + k]);
        ++a.paths;
        a.same_paths += same;
        i = i_end;
        j = j_end;
    }
    return a;
}

}  // namespace kdpm::bench
