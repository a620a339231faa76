#include "robot/linkfaults.h"

#include <cmath>

namespace hatpic::robot {

std::vector<Violation> validate(const LinkFaults &faults)
{
    std::vector<Violation> out;
    const auto check = [&](const char *field, double value, double max, const char *rule) {
        if (!std::isfinite(value))
            out.push_back({field, -1, "must be a finite number", value});
        else if (value < 0 || value > max)
            out.push_back({field, -1, rule, value});
    };
    check("delay", faults.delay, kMaxLinkDelay, "must be from 0 to 10 s");
    check("jitter", faults.jitter, kMaxLinkDelay, "must be from 0 to 10 s");
    check("loss", faults.loss, 1, "must be from 0 to 1");
    return out;
}

} // namespace hatpic::robot
