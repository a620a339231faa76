// Invariant checks for the fuzz targets: a broken invariant prints where and aborts, which
// libFuzzer reports as a crash and saves the input.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition)                                                                      \
    do {                                                                                           \
        if (!(condition)) {                                                                        \
            std::fprintf(stderr, "%s:%d: invariant broken: %s\n", __FILE__, __LINE__, #condition); \
            std::abort();                                                                          \
        }                                                                                          \
    } while (false)

namespace fuzzcheck {

//! A small deterministic generator: the harnesses derive chunk sizes and schedules from one
//! input byte with it, so a crashing input replays exactly.
class XorShift
{
public:
    explicit XorShift(std::uint32_t seed) : m_state(seed * 2654435761u + 1u) {}
    std::uint32_t next()
    {
        m_state ^= m_state << 13;
        m_state ^= m_state >> 17;
        m_state ^= m_state << 5;
        return m_state;
    }
    //! 1 … limit.
    std::size_t chunk(std::size_t limit) { return 1 + next() % limit; }

private:
    std::uint32_t m_state;
};

} // namespace fuzzcheck
