// `lpv compare` on image bombs (issue #42): it aborted with std::length_error
// (GIF logical screen) and std::bad_alloc (EXR with 16 channels of 16384^2),
// exit 134. Now: exit 1 and the header's claim against the budget.
#include "../cli/RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path writeFile(const std::string& name, const std::string& bytes) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-image-budget-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return dir / name;
}

std::string le16(unsigned v) {
    return {char(v & 0xFF), char(v >> 8 & 0xFF)};
}
std::string le32(unsigned v) {
    return le16(v & 0xFFFF) + le16(v >> 16);
}

} // namespace

TEST(ImageBudgetCli, CompareOnTheGifBombExitsOneWithTheClaim) {
    std::string gif = "GIF89a" + le16(65535) + le16(65535) + std::string("\x80\x00\x00\0\0\0\xff\xff\xff", 9);
    gif += "," + le16(0) + le16(0) + le16(1) + le16(1) + std::string("\0\x02\x02\x44\x01\x00;", 7);
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
    std::string b("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    auto attr = [&](const std::string& name, const std::string& kind, const std::string& value) {
        b += name + '\0' + kind + '\0' + le32(unsigned(value.size())) + value;
    };
    std::string list;
    for (int c = 0; c < 16; ++c)
        list += "c" + std::to_string(c) + '\0' + le32(1) + std::string(4, '\0') + le32(1) + le32(1);
    attr("channels", "chlist", list + '\0');
    attr("compression", "compression", std::string(1, '\3'));
    const std::string box = le32(0) + le32(0) + le32(16383) + le32(16383);
    attr("dataWindow", "box2i", box);
    attr("displayWindow", "box2i", box);
    attr("lineOrder", "lineOrder", std::string(1, '\0'));
    attr("pixelAspectRatio", "float", le32(0x3f800000));
    attr("screenWindowCenter", "v2f", std::string(8, '\0'));
    attr("screenWindowWidth", "float", le32(0x3f800000));
    b += '\0';
    const fs::path f = writeFile("a.exr", b);
    const RunResult r = runLpv("compare " + f.string() + " " + f.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(f.string() +
                            ": header: claims 16384x16384 pixels, 16 channels of 2 bytes (openexr, zip): "
                            "8.0 GiB to decode; the budget is 1.0 GiB per image"),
              std::string::npos)
        << r.output;
}
