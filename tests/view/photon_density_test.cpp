#include <catch2/catch.hpp>

#include <vector>

#include "formats/kd_node.h"
#include "runtime/view/photon_density.h"

using namespace kdpm;

TEST_CASE("photon density of a uniform grid matches photons per unit area", "[view][density]") {
    // Photons every 0.01 on the unit square z = 0: 10,000 per unit area.
    const int n = 101;
    std::vector<float> x, y, z;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            x.push_back(static_cast<float>(i) * 0.01f);
            y.push_back(static_cast<float>(j) * 0.01f);
            z.push_back(0.0f);
        }
    std::vector<KdNode> nodes{KdNode::leaf(0, static_cast<std::uint32_t>(x.size()))};
    PhotonMapView map;
    map.nodes = nodes.data();
    map.node_count = 1;
    map.photon_count = static_cast<std::uint32_t>(x.size());
    map.x = x.data();
    map.y = y.data();
    map.z = z.data();

    // Two hit pixels (centre, a quarter in) and one miss (zero normal).
    const std::vector<float> positions{0.5f, 0.5f, 0.0f, 0.25f, 0.25f, 0.0f, 0.5f, 0.5f, 0.0f};
    const std::vector<float> normals{0, 0, 1, 0, 0, 1, 0, 0, 0};
    for (std::uint32_t k : {16u, 64u, 256u}) {
        INFO("k = " << k);
        const auto d = photon_density(map, positions, normals, k);
        REQUIRE(d.size() == 3);
        CHECK(d[0] == Approx(10000.0f).epsilon(0.2));
        CHECK(d[1] == Approx(10000.0f).epsilon(0.2));
        CHECK(d[2] == 0.0f);
    }
    // An empty map gives zero everywhere.
    const auto none = photon_density(PhotonMapView{}, positions, normals, 32);
    CHECK(none == std::vector<float>(3, 0.0f));
}
