// Clock over esp_timer: microseconds since boot, truncated to 32 bits (wraps every ~71.6 min,
// as the device core expects). Safe from any task.
#pragma once

#include "firmware/ports.h"

#include <esp_timer.h>

#include <cstdint>

namespace hatpic::esp32 {

class EspClock final : public fw::Clock
{
public:
    std::uint32_t micros() override { return static_cast<std::uint32_t>(esp_timer_get_time()); }
};

} // namespace hatpic::esp32
