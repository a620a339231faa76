#include "numbertext.h"

#include <charconv>
#include <cmath>

namespace hatpic {

QString compactNumberText(double value)
{
    if (std::isnan(value))
        return QStringLiteral("nan");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    if (value == 0.0)
        return QStringLiteral("0");
    char buffer[32];
    std::to_chars_result result;
    const auto asFloat = static_cast<float>(value);
    if (static_cast<double>(asFloat) == value)
        result = std::to_chars(buffer, buffer + sizeof buffer, asFloat);
    else
        result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return QString::fromLatin1(buffer, result.ptr - buffer);
}

} // namespace hatpic
