#include "lpv/radiosity/Hemicube.h"

#include <gtest/gtest.h>

#include <numeric>

using namespace lpv::radiosity;

TEST(Hemicube, DeltaFormFactorsSumToOne) {
    for (int res : {32, 64, 128, 256}) {
        const auto dff = deltaFormFactors(res);
        ASSERT_EQ(dff.size(), std::size_t(3 * res * res));
        const double sum = std::accumulate(dff.begin(), dff.end(), 0.0);
        EXPECT_NEAR(sum, 1.0, 1e-3) << "resolution " << res;
    }
}

TEST(Hemicube, TopFaceCentreOutweighsItsCornerAndSidesFadeToTheHorizon) {
    const int res = 64;
    const auto dff = deltaFormFactors(res);
    const int w = 3 * res;
    const float centre = dff[std::size_t(res / 2 * w + res / 2)];
    const float corner = dff[0];
    EXPECT_NEAR(centre / corner, 9.0f, 0.5f); // (x^2 + y^2 + 1)^2 = 9 at the corner
    // Side face 1 starts at x = res: its bottom row (horizon) has almost no weight.
    EXPECT_LT(dff[std::size_t(res + res / 2)], 0.1f * dff[std::size_t((res / 2 - 1) * w + res + res / 2)]);
}

TEST(Hemicube, LayoutTilesTheImageWithoutOverlap) {
    const HemicubeLayout layout{32};
    std::vector<int> covered(std::size_t(layout.width() * layout.height()), 0);
    for (const auto& f : layout.faces())
        for (int y = f.y; y < f.y + f.height; ++y)
            for (int x = f.x; x < f.x + f.width; ++x)
                ++covered[std::size_t(y * layout.width() + x)];
    for (int c : covered)
        ASSERT_EQ(c, 1);
}
