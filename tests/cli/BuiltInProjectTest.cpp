#include "RunLpv.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

// The committed project must be exactly what its generator produces, so the
// code in the repository stays the source of truth for the Cornell box.
TEST(BuiltInProject, CornellBoxMatchesItsGenerator) {
    auto loaded = lpv::scene::loadProject(lpv::test::cornellProject());
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_TRUE(*loaded == lpv::scene::makeCornellBoxProject())
        << "run `cmake --build build --target regenerate-projects` and commit the result";
}
