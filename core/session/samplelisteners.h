// The robot path's way out of the session: every complete sample, handed to each listener on
// the session thread the moment it is decoded — before any batch, timer or other thread. The
// GUI and the recorder take batches (SamplePipeline::samplesReady); what must not wait for them
// (the robot bridge) listens here.
#pragma once

#include "telemetry/sample.h"

#include <mutex>
#include <vector>

namespace hatpic {

class SampleListener
{
public:
    //! On the session thread, once per sample as it is decoded (`sample.arrival_ns` is when).
    //! It must return quickly and never wait for another thread's event loop.
    virtual void sampleDecoded(const Sample &sample) = 0;

protected:
    ~SampleListener() = default;
};

//! The listeners of one session. add() and remove() may be called from any thread; dispatch()
//! runs on the session thread. After remove() returns, the listener is never called again (a
//! call in progress is waited for), so a listener may be destroyed then.
class SampleListeners
{
public:
    void add(SampleListener *listener)
    {
        const std::lock_guard lock(m_mutex);
        m_listeners.push_back(listener);
    }
    void remove(SampleListener *listener)
    {
        const std::lock_guard lock(m_mutex);
        std::erase(m_listeners, listener);
    }
    void dispatch(const Sample &sample)
    {
        const std::lock_guard lock(m_mutex);
        for (SampleListener *listener : m_listeners)
            listener->sampleDecoded(sample);
    }

private:
    std::mutex m_mutex; //!< held while listeners run: remove() waits for a call in progress
    std::vector<SampleListener *> m_listeners;
};

} // namespace hatpic
