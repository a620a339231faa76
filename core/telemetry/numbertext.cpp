#include "numbertext.h"

#include <charconv>
#include <cmath>

namespace hatpic {

QByteArray compactNumber(double value)
{
    if (std::isnan(value))
        return QByteArrayLiteral("nan");
    if (std::isinf(value))
        return value > 0 ? QByteArrayLiteral("inf") : QByteArrayLiteral("-inf");
    if (value == 0.0)
        return QByteArrayLiteral("0"); // also −0 (e.g. −K_rec·0), which reads as noise in a table
    char buffer[32];
    std::to_chars_result result;
    const auto asFloat = static_cast<float>(value);
    if (static_cast<double>(asFloat) == value)
        result = std::to_chars(buffer, buffer + sizeof buffer, asFloat);
    else
        result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return QByteArray(buffer, result.ptr - buffer);
}

QString compactNumberText(double value)
{
    return QString::fromLatin1(compactNumber(value));
}

} // namespace hatpic
