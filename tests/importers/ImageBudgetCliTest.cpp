// `lpv compare` on image bombs (issue #42): it aborted with std::length_error
// (GIF logical screen) and std::bad_alloc (EXR with 16 channels of 16384^2),
// exit 134. Now: exit 1 and the header's claim against the budget.
#include "../cli/RunLpv.h"
#include "ImageBombs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path writeFile(const std::string& name, const std::string& bytes) {
    return bombs::writeTempFile("lpv-image-budget-cli", name, bytes);
}

} // namespace

TEST(ImageBudgetCli, CompareOnTheGifBombExitsOneWithTheClaim) {
    const std::string gif = bombs::gifBomb(65535, 65535);
    ASSERT_EQ(gif.size(), 35u);
    const fs::path f = writeFile("a.gif", gif);
    const RunResult r = runLpv("compare " + f.string() + " " + f.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(r.output,
              "lpv: " + f.string() +
                  ": header: claims 65535x65535 pixels, 4 channels of 1 byte (gif, lzw): 16.0 GiB to "
                  "decode; the budget is 1.0 GiB per image\n");
}

TEST(ImageBudgetCli, CompareOnAnExrOfSixteenChannelsExitsOneWithTheClaim) {
    const fs::path f = writeFile("a.exr", bombs::exrHeader(16384, 16384, 16, 1, 3));
    const RunResult r = runLpv("compare " + f.string() + " " + f.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(f.string() +
                            ": header: claims 16384x16384 pixels, 16 channels of 2 bytes (openexr, zip): "
                            "8.0 GiB to decode; the budget is 1.0 GiB per image"),
              std::string::npos)
        << r.output;
}
