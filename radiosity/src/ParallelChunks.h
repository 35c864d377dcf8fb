#pragma once
// Work over [0, count) cut into chunks that every core takes in turn: the
// lights' direct light and the ray-cast form factors both run per patch.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace lpv::radiosity {

// Calls work(begin, end) for consecutive chunks of at most `chunk` items on
// all hardware threads (the caller's included) and returns when all are
// done; a set `cancel` (may be null) stops handing out chunks.
template <class Work>
void forEachChunk(std::size_t count, std::size_t chunk, Work&& work,
                  const std::atomic<bool>* cancel = nullptr) {
    std::atomic<std::size_t> next{0};
    auto run = [&] {
        for (;;) {
            if (cancel && cancel->load())
                return;
            const std::size_t begin = next.fetch_add(chunk);
            if (begin >= count)
                return;
            work(begin, std::min(begin + chunk, count));
        }
    };
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(run);
    run();
    for (std::thread& t : pool)
        t.join();
}

} // namespace lpv::radiosity
