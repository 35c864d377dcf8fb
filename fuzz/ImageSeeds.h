#pragma once
// The generated seeds of fuzz_image (fuzz/ImageFuzzer.cpp), written by
// fuzz_seeds (fuzz/SeedGenerator.cpp): small valid images of every format
// textures arrive in (PNG grey/RGB/RGBA, JPEG, GIF, BMP, TGA, EXR half and
// float, a multi-channel EXR like the reference's), and the header bombs of
// issue #42 (the same files with headers that claim huge canvases or
// channel counts), so the fuzzer starts where those bugs were.
#include <cstddef>
#include <filesystem>

namespace lpv::fuzz {

// Writes the seeds into `out` (created); returns how many. Exits on failure.
std::size_t writeImageSeeds(const std::filesystem::path& out);

} // namespace lpv::fuzz
