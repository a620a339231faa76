#include "request.h"

#include "model/overloaded.h"

namespace hatpic {

QString commandName(CommandKind kind)
{
    return QString::fromLatin1(v2::messageName(kind));
}

std::vector<CommandKind> wireSteps(const Request &request, const DeviceInfo &device)
{
    return std::visit(
        Overloaded{
            [](const request::Push &push) {
                // Each part sent, then read back (push_back: GCC 12 at -O3 warns of a false
                // overflow in an insert of an initializer list here).
                std::vector<CommandKind> steps;
                const auto sendAndRead = [&steps](CommandKind set, CommandKind get) {
                    steps.push_back(set);
                    steps.push_back(get);
                };
                if (push.tuning.params)
                    sendAndRead(CommandKind::SetParams, CommandKind::GetParams);
                if (push.tuning.effects)
                    sendAndRead(CommandKind::SetEffects, CommandKind::GetEffects);
                if (push.tuning.passivity)
                    sendAndRead(CommandKind::SetPassivity, CommandKind::GetPassivity);
                return steps;
            },
            [&device](const request::Read &) {
                std::vector<CommandKind> steps{CommandKind::GetParams};
                if (device.hasEffects())
                    steps.push_back(CommandKind::GetEffects);
                if (device.hasPassivity())
                    steps.push_back(CommandKind::GetPassivity);
                return steps;
            },
            [](const request::Zero &) {
                return std::vector{CommandKind::Zero, CommandKind::GetParams};
            },
            [](const request::Save &) { return std::vector{CommandKind::SaveParams}; },
            [](const request::Stream &) { return std::vector{CommandKind::SetStream}; },
            [](const request::Vibrate &) { return std::vector{CommandKind::Vibrate}; },
        },
        request);
}

Knob knobOf(const Request &request)
{
    return std::visit(
        [](const auto &r) -> Knob {
            if constexpr (requires { r.knob; })
                return r.knob;
            else
                return 0;
        },
        request);
}

const outcome::Stopped *Outcome::stopped() const
{
    return std::visit(
        [](const auto &r) -> const outcome::Stopped * {
            if constexpr (std::is_base_of_v<outcome::Stopped, std::decay_t<decltype(r)>>)
                return &r;
            else
                return nullptr;
        },
        result);
}

const DeviceTuning *Outcome::pushed() const
{
    const auto *push = std::get_if<request::Push>(&request);
    return push ? &push->tuning : nullptr;
}

std::optional<CommandKind> Outcome::unknownStep() const
{
    const outcome::Stopped *stop = stopped();
    const DeviceTuning *sent = pushed();
    if (!stop || !sent || std::holds_alternative<outcome::Refused>(result))
        return std::nullopt;
    if ((stop->step == CommandKind::SetEffects && sent->effects) ||
        (stop->step == CommandKind::SetPassivity && sent->passivity))
        return stop->step;
    return std::nullopt;
}

} // namespace hatpic
