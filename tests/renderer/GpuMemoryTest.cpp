// GpuMemory's arithmetic without a GL context: bytes per texel of every
// format the renderer allocates, mip chains, and how bytes are printed.
#include "gl/GpuMemoryLedger.h"

#include <gtest/gtest.h>

using namespace lpv::renderer;
using graph::ResourceDesc;
using graph::ResourceKind;

TEST(GpuMemory, BytesPerTexelOfEveryFormatTheRendererAllocates) {
    EXPECT_EQ(bytesPerTexel(GL_RGBA32F), 16u);
    EXPECT_EQ(bytesPerTexel(GL_RGBA16F), 8u);
    EXPECT_EQ(bytesPerTexel(GL_RGBA8), 4u);
    EXPECT_EQ(bytesPerTexel(GL_SRGB8_ALPHA8), 4u);
    EXPECT_EQ(bytesPerTexel(GL_RG16F), 4u);
    EXPECT_EQ(bytesPerTexel(GL_R32F), 4u);
    EXPECT_EQ(bytesPerTexel(GL_R32UI), 4u);
    EXPECT_EQ(bytesPerTexel(GL_R16F), 2u);
    EXPECT_EQ(bytesPerTexel(GL_DEPTH_COMPONENT32F), 4u);
}

// An unknown format is 0, which the GL test's "no allocation has 0 bytes" reports by name.
TEST(GpuMemory, UnknownFormatHasNoSize) {
    EXPECT_EQ(bytesPerTexel(0), 0u);
    EXPECT_EQ(bytesPerTexel(GL_COMPRESSED_RGBA_S3TC_DXT1_EXT), 0u);
    EXPECT_EQ(bytesPerTexel(GL_DEPTH24_STENCIL8), 0u);
    EXPECT_EQ(textureBytes({ResourceKind::Texture2D, 0, 4, 4}, 1), 0u);
}

TEST(GpuMemory, TextureBytesCountEveryLevel) {
    // 2D RGBA8 4x4, 3 levels: 16 + 4 + 1 texels.
    EXPECT_EQ(textureBytes({ResourceKind::Texture2D, GL_RGBA8, 4, 4}, 3), (16u + 4u + 1u) * 4u);
    // 2D array 8x4 of 6 layers, 2 levels: the layers stay.
    EXPECT_EQ(textureBytes({ResourceKind::Texture2DArray, GL_R32F, 8, 4, 6}, 2), (32u + 8u) * 6u * 4u);
    // 3D 4x4x4, 3 levels: the depth halves too.
    EXPECT_EQ(textureBytes({ResourceKind::Texture3D, GL_RGBA32F, 4, 4, 4}, 3), (64u + 8u + 1u) * 16u);
    // A cube-map array's depth is its layer-faces (2 cubes: 12).
    EXPECT_EQ(textureBytes({ResourceKind::CubeMapArray, GL_DEPTH_COMPONENT32F, 16, 16, 12}, 1),
              16u * 16u * 12u * 4u);
    // An LPV volume: 32^3 cells of 4 cascades stacked along z.
    EXPECT_EQ(textureBytes({ResourceKind::Texture3D, GL_RGBA32F, 32, 32, 128}, 1), 32u * 32u * 128u * 16u);
    ResourceDesc buffer{ResourceKind::Buffer};
    buffer.bytes = 1234;
    EXPECT_EQ(textureBytes(buffer, 1), 1234u);
}

TEST(GpuMemory, FormatBytes) {
    EXPECT_EQ(formatBytes(0), "0 B");
    EXPECT_EQ(formatBytes(512), "512 B");
    EXPECT_EQ(formatBytes(1023), "1023 B");
    EXPECT_EQ(formatBytes(1024), "1 KiB");
    EXPECT_EQ(formatBytes(1536), "1.5 KiB");
    EXPECT_EQ(formatBytes(640 * 1024), "640 KiB");
    EXPECT_EQ(formatBytes(std::uint64_t(12.3 * 1024 * 1024)), "12.3 MiB");
    EXPECT_EQ(formatBytes(std::uint64_t(1) << 30), "1 GiB");
    EXPECT_EQ(formatBytes(3 * (std::uint64_t(1) << 40)), "3 TiB");
}

TEST(GpuMemory, BytesOfAndFind) {
    GpuMemory m;
    m.allocations = {{"lpv.volumes", "", 600}, {"camera.hdr", "", 300}, {"lpv.geometry", "", 100}};
    m.totalBytes = 1000;
    EXPECT_EQ(m.bytesOf("lpv."), 700u);
    EXPECT_EQ(m.bytesOf(""), 1000u);
    ASSERT_NE(m.find("camera.hdr"), nullptr);
    EXPECT_EQ(m.find("camera.hdr")->bytes, 300u);
    EXPECT_EQ(m.find("camera"), nullptr);
}
