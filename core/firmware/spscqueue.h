// A bounded single-producer single-consumer queue: how the control task and the link task
// exchange plain structs without locks (the ESP32's two tasks, or one thread in the simulator).
//
// Plain C++20, no allocation: the storage is a fixed array. One thread pushes, one pops.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace hatpic::fw {

template<typename T, std::size_t N> class SpscQueue
{
    static_assert(N >= 2 && (N & (N - 1)) == 0, "capacity must be a power of two");

public:
    //! Producer: false (and nothing queued) when full.
    bool push(const T &item)
    {
        const std::uint32_t head = m_head.load(std::memory_order_relaxed);
        if (head - m_tail.load(std::memory_order_acquire) >= N)
            return false;
        m_items[head & (N - 1)] = item;
        m_head.store(head + 1, std::memory_order_release);
        return true;
    }
    //! Consumer: false when empty.
    bool pop(T &item)
    {
        const std::uint32_t tail = m_tail.load(std::memory_order_relaxed);
        if (tail == m_head.load(std::memory_order_acquire))
            return false;
        item = m_items[tail & (N - 1)];
        m_tail.store(tail + 1, std::memory_order_release);
        return true;
    }
    static constexpr std::size_t capacity() { return N; }

private:
    std::array<T, N> m_items{};
    std::atomic<std::uint32_t> m_head{0}; //!< written by the producer only
    std::atomic<std::uint32_t> m_tail{0}; //!< written by the consumer only
};

} // namespace hatpic::fw
