#include "paramsjson.h"

#include "model/paramtable.h"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace hatpic {

namespace {

QString latin1(std::string_view text)
{
    return QString::fromLatin1(text.data(), static_cast<qsizetype>(text.size()));
}

// The keys of a `host` object, in the order they are written.
const char *const kHostMode = "mode";
const char *const kHostRefDeadzone = "ref_deadzone";

} // namespace

QByteArray jsonNumber(double value)
{
    if (!std::isfinite(value))
        return QByteArrayLiteral("null");
    // Negative zero is written as 0.0: Qt's JSON reader keeps integral numbers as integers,
    // which have no sign of zero, so "-0.0" would read back as +0.0 and then be rewritten
    // differently. Every rule and formula of the model treats the two zeros alike.
    if (value == 0.0)
        return QByteArrayLiteral("0.0");

    // Shortest round-trip digits, in scientific form: "-d.ddde±XX".
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
    const std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
    const std::size_t ePos = text.find('e');
    const bool negative = text.front() == '-';
    std::string digits;
    for (char c : text.substr(negative ? 1 : 0, ePos - (negative ? 1 : 0))) {
        if (c != '.')
            digits += c;
    }
    int exponent = 0;
    const std::string_view expText = text.substr(ePos + 1);
    std::from_chars(expText.data() + (expText.front() == '+' ? 1 : 0),
                    expText.data() + expText.size(), exponent);

    // value = 0.d1d2…dn × 10^(exponent+1)
    std::string out = negative ? "-" : "";
    const int count = static_cast<int>(digits.size());
    if (exponent >= -5 && exponent < 16) {
        if (exponent < 0) {
            out += "0.";
            out.append(static_cast<std::size_t>(-exponent - 1), '0');
            out += digits;
        } else if (exponent + 1 >= count) {
            out += digits;
            out.append(static_cast<std::size_t>(exponent + 1 - count), '0');
            out += ".0";
        } else {
            out += digits.substr(0, static_cast<std::size_t>(exponent + 1));
            out += '.';
            out += digits.substr(static_cast<std::size_t>(exponent + 1));
        }
    } else {
        out += digits.front();
        if (count > 1) {
            out += '.';
            out += digits.substr(1);
        }
        out += 'e';
        out += std::to_string(exponent);
    }
    return QByteArray::fromStdString(out);
}

QByteArray jsonString(const QString &text)
{
    QByteArray out;
    out += '"';
    const QByteArray utf8 = text.toUtf8();
    for (const char c : utf8) {
        const auto byte = static_cast<unsigned char>(c);
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (byte < 0x20) {
                static constexpr char kHex[] = "0123456789abcdef";
                out += "\\u00";
                out += kHex[byte >> 4];
                out += kHex[byte & 0xf];
            } else {
                out += c;
            }
        }
    }
    out += '"';
    return out;
}

QByteArray jsonBool(bool value)
{
    return value ? QByteArrayLiteral("true") : QByteArrayLiteral("false");
}

QString jsonValueText(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return QString::fromStdString(formatNumber(value.toDouble()));
    case QJsonValue::String:
        return u'"' + QString::fromStdString(echoedText(value.toString().toStdString())) + u'"';
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

JsonObjectWriter &JsonObjectWriter::add(const char *key, const QByteArray &rawValue)
{
    m_items.append(QByteArray(m_indent + 2, ' ') + '"' + key + "\": " + rawValue);
    return *this;
}

QByteArray JsonObjectWriter::text() const
{
    if (m_items.isEmpty())
        return QByteArrayLiteral("{}");
    return "{\n" + m_items.join(",\n") + '\n' + QByteArray(m_indent, ' ') + '}';
}

namespace {

// The table's names are literals, so their data() ends in a NUL.
template<typename Params>
void addNumber(JsonObjectWriter &writer, const FieldSpec<Params> &f, const Params &params)
{
    writer.add(f.name.data(), jsonNumber(params.*f.member));
}

template<typename Params, std::size_t N>
void addNumbers(JsonObjectWriter &writer, const std::array<FieldSpec<Params>, N> &table,
                const Params &params)
{
    for (const FieldSpec<Params> &f : table)
        addNumber(writer, f, params);
}

// Reads the table's number fields of `object` into `params` and appends their keys to `known`.
// A key that is missing is an error only when `required`; one that holds no number always is.
// Returns which fields were set.
template<typename Params, std::size_t N>
std::array<bool, N> readNumbers(const std::array<FieldSpec<Params>, N> &table,
                                const QJsonObject &object, const QString &prefix, bool required,
                                Params &params, QStringList &errors, QStringList &known)
{
    std::array<bool, N> present{};
    for (std::size_t i = 0; i < N; ++i) {
        const QString name = latin1(table[i].name);
        known.append(name);
        const QJsonValue value = object.value(name);
        if (value.isUndefined()) {
            if (required)
                errors.append(prefix + name + u": missing, must be a number");
        } else if (!value.isDouble()) {
            errors.append(prefix + name + u": must be a number, got " + jsonValueText(value));
        } else {
            params.*table[i].member = value.toDouble();
            present[i] = true;
        }
    }
    return present;
}

} // namespace

JsonObjectWriter deviceParamsWriter(const DeviceParams &params, int indent)
{
    JsonObjectWriter writer(indent);
    addNumbers(writer, kDeviceFields, params);
    return writer;
}

QByteArray deviceParamsJson(const DeviceParams &params, int indent)
{
    return deviceParamsWriter(params, indent).text();
}

QByteArray effectParamsJson(const EffectParams &effects, int indent)
{
    JsonObjectWriter writer(indent);
    addNumbers(writer, kEffectFields, effects);
    return writer.text();
}

QByteArray passivityParamsJson(const PassivityParams &passivity, int indent)
{
    JsonObjectWriter writer(indent);
    addNumbers(writer, kPassivityFields, passivity);
    return writer.text();
}

JsonObjectWriter hostParamsWriter(const HostParams &params, int indent)
{
    // profile.md's order, the number fields between the others.
    JsonObjectWriter writer(indent);
    writer.add(kHostMode, jsonString(latin1(referenceModeName(params.mode))));
    addNumber(writer, fieldNamed(kHostFields, "v_max"), params);
    writer.add(kHostRefDeadzone, jsonBool(params.ref_deadzone));
    addNumber(writer, fieldNamed(kHostFields, "tau_limit"), params);
    return writer;
}

QByteArray hostParamsJson(const HostParams &params, int indent)
{
    return hostParamsWriter(params, indent).text();
}

std::array<bool, DeviceParams::kFieldCount>
readDeviceParams(const QJsonObject &object, const QString &prefix, DeviceParams &params,
                 QStringList &errors, QStringList *warnings, const QStringList &otherKeys)
{
    QStringList known = otherKeys;
    const auto present = readNumbers(kDeviceFields, object, prefix, true, params, errors, known);
    if (warnings)
        warnUnknownKeys(object, known, prefix, *warnings);
    return present;
}

namespace {

//! An optional block's object: a missing key keeps its value, unknown keys are warnings.
template<typename Params, std::size_t N>
std::array<bool, N> readBlock(const std::array<FieldSpec<Params>, N> &table,
                              const QJsonObject &object, const QString &prefix, Params &params,
                              QStringList &errors, QStringList &warnings)
{
    QStringList known;
    const auto present = readNumbers(table, object, prefix, false, params, errors, known);
    warnUnknownKeys(object, known, prefix, warnings);
    return present;
}

} // namespace

std::array<bool, EffectParams::kFieldCount>
readEffectParams(const QJsonObject &object, const QString &prefix, EffectParams &effects,
                 QStringList &errors, QStringList &warnings)
{
    return readBlock(kEffectFields, object, prefix, effects, errors, warnings);
}

std::array<bool, PassivityParams::kFieldCount>
readPassivityParams(const QJsonObject &object, const QString &prefix, PassivityParams &passivity,
                    QStringList &errors, QStringList &warnings)
{
    return readBlock(kPassivityFields, object, prefix, passivity, errors, warnings);
}

QStringList readHostParams(const QJsonObject &object, const QString &prefix, HostParams &params,
                           QStringList &errors, QStringList *warnings, const QStringList &otherKeys)
{
    const QString mode = QString::fromLatin1(kHostMode);
    const QString refDeadzone = QString::fromLatin1(kHostRefDeadzone);
    if (const QJsonValue value = object.value(mode); !value.isUndefined()) {
        const QString text = value.isString() ? value.toString() : QString();
        if (text == latin1(referenceModeName(ReferenceMode::Translation)))
            params.mode = ReferenceMode::Translation;
        else if (text == latin1(referenceModeName(ReferenceMode::Rotation)))
            params.mode = ReferenceMode::Rotation;
        else
            errors.append(prefix + mode + u": must be \"translation\" or \"rotation\", got " +
                          jsonValueText(value));
    }
    if (const QJsonValue value = object.value(refDeadzone); !value.isUndefined()) {
        if (value.isBool())
            params.ref_deadzone = value.toBool();
        else
            errors.append(prefix + refDeadzone + u": must be true or false, got " +
                          jsonValueText(value));
    }
    QStringList known = QStringList{mode, refDeadzone} + otherKeys;
    const auto present = readNumbers(kHostFields, object, prefix, false, params, errors, known);
    if (warnings)
        warnUnknownKeys(object, known, prefix, *warnings);
    QStringList nonNumbers;
    for (std::size_t i = 0; i < kHostFields.size(); ++i) {
        const QString name = latin1(kHostFields[i].name);
        if (!present[i] && object.contains(name))
            nonNumbers.append(name);
    }
    return nonNumbers;
}

void warnUnknownKeys(const QJsonObject &object, const QStringList &known, const QString &prefix,
                     QStringList &warnings)
{
    qsizetype unknown = 0;
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (known.contains(it.key()))
            continue;
        if (++unknown <= kMaxUnknownKeysNamed) {
            warnings.append(
                u"unknown key \"" +
                QString::fromStdString(echoedText(QString(prefix + it.key()).toStdString())) +
                u"\" ignored");
        }
    }
    if (unknown > kMaxUnknownKeysNamed) {
        const QString where =
            prefix.isEmpty()
                ? QStringLiteral("the file")
                : u'"' +
                      QString::fromStdString(
                          echoedText(prefix.chopped(prefix.endsWith(u'.') ? 1 : 0).toStdString())) +
                      u'"';
        warnings.append(u"… and " + QString::number(unknown - kMaxUnknownKeysNamed) +
                        u" more unknown keys in " + where + u" ignored");
    }
}

} // namespace hatpic
