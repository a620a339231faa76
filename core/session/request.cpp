#include "request.h"

#include "model/overloaded.h"
#include "model/params.h"
#include "model/passivity.h"

#include <iterator>

namespace hatpic {

QString commandName(CommandKind kind)
{
    return QString::fromLatin1(v2::messageName(kind));
}

// GCC 12 at -O3 warns that the byte of a disengaged optional<uint8_t> (a knob's `axis`) "may be
// used uninitialized" when a message is copied into its variant: a false positive (the copy of
// a trivially copyable optional copies its bytes; nothing reads the value).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

std::vector<WireStep> wireSteps(const Request &request, const DeviceInfo &device)
{
    // Knob 1 goes without the byte, so a single-knob device's frames are as they always were.
    const Knob knob = knobOf(request);
    const v2::AxisIndex axis = knob ? v2::AxisIndex(knob) : std::nullopt;
    std::vector<WireStep> steps;
    const auto add = [&steps](v2::Message message) { steps.push_back({std::move(message)}); };
    std::visit(Overloaded{
                   [&](const request::Push &push) {
                       // Each part sent, then read back.
                       const DeviceTuning &t = push.tuning;
                       if (t.params) {
                           add(v2::SetParams{*t.params, axis});
                           add(v2::GetParams{axis});
                       }
                       if (t.effects) {
                           add(v2::SetEffects{*t.effects, axis});
                           add(v2::GetEffects{axis});
                       }
                       if (t.passivity) {
                           add(v2::SetPassivity{*t.passivity, axis});
                           add(v2::GetPassivity{axis});
                       }
                   },
                   [&](const request::Read &) {
                       add(v2::GetParams{axis});
                       if (device.hasEffects())
                           add(v2::GetEffects{axis});
                       if (device.hasPassivity())
                           add(v2::GetPassivity{axis});
                   },
                   [&](const request::Zero &) {
                       add(v2::Zero{axis});
                       add(v2::GetParams{axis});
                   },
                   [&](const request::Save &) { add(v2::SaveParams{}); },
                   [&](const request::Stream &stream) { add(v2::SetStream{stream.rateHz}); },
                   [&](const request::Vibrate &cue) {
                       const Vibration &v = cue.vibration;
                       add(v2::Vibrate{static_cast<float>(v.amplitude),
                                       static_cast<float>(v.frequency),
                                       static_cast<float>(v.duration), axis});
                   },
               },
               request);
    return steps;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

std::vector<CommandKind> stepKinds(const std::vector<WireStep> &steps)
{
    std::vector<CommandKind> kinds;
    kinds.reserve(steps.size());
    for (const WireStep &step : steps)
        kinds.push_back(step.kind());
    return kinds;
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

std::string_view outcome::Refused::fieldName() const
{
    if (field < 0)
        return {};
    switch (step) {
    case CommandKind::SetParams:
        return deviceFieldName(field);
    case CommandKind::SetEffects:
        return effectFieldName(field);
    case CommandKind::SetPassivity:
        return passivityFieldName(field);
    case CommandKind::Vibrate: {
        constexpr std::string_view kCue[] = {"amplitude", "frequency", "duration"};
        return field < int(std::size(kCue)) ? kCue[field] : std::string_view();
    }
    default:
        return {};
    }
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
