#include "profile.h"

#include "jsonkeys.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QSaveFile>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

// Q_INIT_RESOURCE must be used outside any namespace.
static void initPresetResources()
{
    Q_INIT_RESOURCE(presets);
}

namespace hatpic {

namespace {

const QString kFormat = QStringLiteral("hatpic-profile");

struct PresetEntry
{
    const char16_t *name;
    const char16_t *path;
};

constexpr std::array<PresetEntry, 3> kPresets = {{
    {u"Default", u":/presets/default.json"},
    {u"Soft", u":/presets/soft.json"},
    {u"Notchy", u":/presets/notchy.json"},
}};

QString number(double value)
{
    return QString::fromStdString(formatNumber(value));
}

// How a JSON value appears after "got " in a message.
QString describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return number(value.toDouble());
    case QJsonValue::String: {
        constexpr qsizetype kMaxShown = 40;
        QString text = value.toString();
        if (text.size() > kMaxShown)
            text = text.left(kMaxShown) + u'…';
        return u'"' + text + u'"';
    }
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

// Reports every key of `object` that is not in `known` as a warning; `prefix` is "" or "device.".
template<std::size_t Count>
void warnUnknownKeys(const QJsonObject &object, const std::array<QStringView, Count> &known,
                     const QString &prefix, QStringList &warnings)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool isKnown = false;
        for (QStringView key : known)
            isKnown = isKnown || key == it.key();
        if (!isKnown)
            warnings.append(u"unknown key \"" + prefix + it.key() + u"\" ignored");
    }
}

// Checks format and version. Returns false when the document is not a profile this build can
// read, in which case nothing else is examined.
bool checkHeader(const QJsonObject &root, QStringList &errors)
{
    const QJsonValue format = root.value(u"format");
    if (format.isUndefined())
        errors.append(u"format: missing, must be \"" + kFormat + u'"');
    else if (format.toString() != kFormat)
        errors.append(u"format: must be \"" + kFormat + u"\", got " + describe(format));

    const QJsonValue version = root.value(u"version");
    const QString versionText = QString::number(kProfileVersion);
    const double v = version.toDouble(std::nan(""));
    const bool integral = version.isDouble() && std::isfinite(v) && v == std::floor(v);
    if (version.isUndefined())
        errors.append(u"version: missing, must be " + versionText);
    else if (integral && v > kProfileVersion)
        errors.append(u"version: the file was written by a newer version of HATPIC Tuner "
                      u"(profile version " +
                      number(v) + u"); this build reads profile version " + versionText);
    else if (!integral || v != kProfileVersion)
        errors.append(u"version: must be " + versionText + u", got " + describe(version));
    return errors.isEmpty();
}

void readOptionalString(const QJsonObject &root, QStringView key, QString &out, QStringList &errors)
{
    const QJsonValue value = root.value(key);
    if (value.isUndefined())
        return;
    if (value.isString())
        out = value.toString();
    else
        errors.append(key + u": must be a string, got " + describe(value));
}

void readDevice(const QJsonObject &root, DeviceParams &device, QStringList &errors,
                QStringList &warnings)
{
    const QJsonValue deviceValue = root.value(u"device");
    if (deviceValue.isUndefined()) {
        errors.append(QStringLiteral("device: missing, must be an object with D_adm, M_adm, "
                                     "K_min, K_max, N, Q_dz and theta0"));
        return;
    }
    if (!deviceValue.isObject()) {
        errors.append(u"device: must be an object, got " + describe(deviceValue));
        return;
    }
    const QJsonObject object = deviceValue.toObject();

    std::array<QStringView, DeviceParams::kFieldCount> known;
    std::array<QString, DeviceParams::kFieldCount> names;
    std::array<bool, DeviceParams::kFieldCount> present{};
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const std::string_view name = deviceFieldName(i);
        const auto slot = static_cast<std::size_t>(i);
        names[slot] = QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
        known[slot] = names[slot];
        const QJsonValue value = object.value(names[slot]);
        if (value.isUndefined()) {
            errors.append(u"device." + names[slot] + u": missing, must be a number");
            device.setField(i, std::nan(""));
        } else if (!value.isDouble()) {
            errors.append(u"device." + names[slot] + u": must be a number, got " + describe(value));
            device.setField(i, std::nan(""));
        } else {
            device.setField(i, value.toDouble());
            present[slot] = true;
        }
    }
    warnUnknownKeys(object, known, QStringLiteral("device."), warnings);

    // Range and cross-field rules. Missing or non-number fields hold NaN: their own
    // "must be finite" is not repeated, and validate() skips cross-field rules against them.
    for (const Violation &v : validate(device)) {
        if (v.index >= 0 && present[static_cast<std::size_t>(v.index)])
            errors.append(u"device." + QString::fromStdString(v.message()));
    }
}

void readHost(const QJsonObject &root, HostParams &host, QStringList &errors, QStringList &warnings)
{
    const QJsonValue hostValue = root.value(u"host");
    if (hostValue.isUndefined())
        return;
    if (!hostValue.isObject()) {
        errors.append(u"host: must be an object, got " + describe(hostValue));
        return;
    }
    const QJsonObject object = hostValue.toObject();
    static constexpr std::array<QStringView, 4> kKnown = {u"mode", u"v_max", u"ref_deadzone",
                                                          u"tau_limit"};
    warnUnknownKeys(object, kKnown, QStringLiteral("host."), warnings);

    if (const QJsonValue mode = object.value(u"mode"); !mode.isUndefined()) {
        const QString text = mode.isString() ? mode.toString() : QString();
        if (text == u"translation")
            host.mode = ReferenceMode::Translation;
        else if (text == u"rotation")
            host.mode = ReferenceMode::Rotation;
        else
            errors.append(u"host.mode: must be \"translation\" or \"rotation\", got " +
                          describe(mode));
    }
    if (const QJsonValue flag = object.value(u"ref_deadzone"); !flag.isUndefined()) {
        if (flag.isBool())
            host.ref_deadzone = flag.toBool();
        else
            errors.append(u"host.ref_deadzone: must be true or false, got " + describe(flag));
    }

    // Numbers: a non-number is reported here and left out of the range rules below.
    QStringList nonNumbers;
    auto readNumber = [&](const QString &key, double &out) {
        const QJsonValue value = object.value(key);
        if (value.isUndefined())
            return;
        if (value.isDouble()) {
            out = value.toDouble();
        } else {
            errors.append(u"host." + key + u": must be a number, got " + describe(value));
            nonNumbers.append(key);
        }
    };
    readNumber(QStringLiteral("v_max"), host.v_max);
    readNumber(QStringLiteral("tau_limit"), host.tau_limit);
    for (const Violation &v : validate(host)) {
        const QString message = QString::fromStdString(v.message());
        if (!nonNumbers.contains(QString::fromStdString(v.field)))
            errors.append(u"host." + message);
    }
}

// A JSON string literal: quotes, backslash and control characters escaped, the rest UTF-8.
void appendJsonString(QByteArray &out, const QString &text)
{
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
}

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

ProfileReadResult parseProfile(const QByteArray &json)
{
    ProfileReadResult result;
    if (json.size() > kMaxProfileBytes) {
        result.errors.append(u"the file is larger than 1 MiB (" +
                             QString::number(kMaxProfileBytes) + u" bytes), got " +
                             QString::number(json.size()) + u" bytes; refused");
        return result;
    }

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        result.errors.append(u"not valid JSON: " + parseError.errorString() + u" at byte offset " +
                             QString::number(parseError.offset));
        return result;
    }
    if (!document.isObject()) {
        const QString got =
            document.isArray() ? QStringLiteral("an array") : QStringLiteral("nothing");
        result.errors.append(u"not a profile: the top level must be a JSON object, got " + got);
        return result;
    }
    if (const QString key = firstDuplicateKey(json); !key.isEmpty()) {
        result.errors.append(u"duplicate key \"" + key +
                             u"\": a key may appear once (which value was meant?)");
        return result;
    }
    const QJsonObject root = document.object();
    // Not a profile at all: its error alone, no word about keys a profile does not have.
    if (!checkHeader(root, result.errors))
        return result;

    static constexpr std::array<QStringView, 6> kTopKeys = {u"format", u"version", u"name",
                                                            u"notes",  u"device",  u"host"};
    warnUnknownKeys(root, kTopKeys, QString(), result.warnings);

    Profile profile;
    readOptionalString(root, u"name", profile.name, result.errors);
    readOptionalString(root, u"notes", profile.notes, result.errors);
    readDevice(root, profile.device, result.errors, result.warnings);
    readHost(root, profile.host, result.errors, result.warnings);

    if (result.errors.isEmpty())
        result.profile = profile;
    return result;
}

ProfileReadResult readProfile(const QString &path)
{
    ProfileReadResult result;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        result.errors.append(u"cannot open profile \"" + path + u"\": " + file.errorString());
        return result;
    }
    // Read at most one byte past the limit: enough to know the file is too large without
    // pulling an arbitrarily large (or endless) file into memory.
    const QByteArray data = file.read(kMaxProfileBytes + 1);
    if (file.error() != QFileDevice::NoError) {
        result.errors.append(u"cannot read profile \"" + path + u"\": " + file.errorString());
        return result;
    }
    if (data.size() > kMaxProfileBytes) {
        const qint64 size = file.size();
        const QString got = size > kMaxProfileBytes ? QString::number(size) + u" bytes"
                                                    : QStringLiteral("more than that");
        result.errors.append(u"profile \"" + path + u"\" is larger than 1 MiB (" +
                             QString::number(kMaxProfileBytes) + u" bytes), got " + got +
                             u"; refused");
        return result;
    }
    return parseProfile(data);
}

QByteArray serializeProfile(const Profile &profile)
{
    QByteArray out;
    out += "{\n";
    out += "  \"format\": ";
    appendJsonString(out, kFormat);
    out += ",\n  \"version\": " + QByteArray::number(kProfileVersion) + ",\n";
    out += "  \"name\": ";
    appendJsonString(out, profile.name);
    out += ",\n  \"notes\": ";
    appendJsonString(out, profile.notes);
    out += ",\n  \"device\": {\n";
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const std::string_view name = deviceFieldName(i);
        out += "    \"";
        out += QByteArrayView(name.data(), static_cast<qsizetype>(name.size()));
        out += "\": " + jsonNumber(profile.device.field(i));
        out += i + 1 < DeviceParams::kFieldCount ? ",\n" : "\n";
    }
    out += "  },\n  \"host\": {\n";
    out += "    \"mode\": ";
    const std::string_view mode = referenceModeName(profile.host.mode);
    appendJsonString(out, QString::fromLatin1(mode.data(), static_cast<qsizetype>(mode.size())));
    out += ",\n    \"v_max\": " + jsonNumber(profile.host.v_max);
    out += ",\n    \"ref_deadzone\": ";
    out += profile.host.ref_deadzone ? "true" : "false";
    out += ",\n    \"tau_limit\": " + jsonNumber(profile.host.tau_limit);
    out += "\n  }\n}\n";
    return out;
}

QString writeProfile(const Profile &profile, const QString &path)
{
    // A profile that could not be read back is not written; the file on disk stays as it was.
    QStringList problems;
    for (const Violation &v : validate(profile.device))
        problems.append(u"device." + QString::fromStdString(v.message()));
    for (const Violation &v : validate(profile.host))
        problems.append(u"host." + QString::fromStdString(v.message()));
    if (!problems.isEmpty())
        return u"refusing to write an invalid profile to \"" + path + u"\": " +
               problems.join(u"; ");

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return u"cannot write profile \"" + path + u"\": " + file.errorString();
    const QByteArray data = serializeProfile(profile);
    // Flush and check before commit(): Qt 6.4's QSaveFile::commit() does not notice when the
    // final flush of its write buffer fails (e.g. EFBIG, ENOSPC) and renames the truncated
    // temporary file over the good one. A short write also comes back without an error text,
    // so the system's errno is kept for the message. See docs/profile.md.
    errno = 0;
    if (file.write(data) != data.size() || !file.flush()) {
        const int systemError = errno;
        file.cancelWriting();
        file.commit(); // discards the temporary file
        const QString reason = systemError != 0 ? qt_error_string(systemError) : file.errorString();
        return u"cannot write profile \"" + path + u"\": " + reason;
    }
    if (!file.commit())
        return u"cannot write profile \"" + path + u"\": " + file.errorString();
    return {};
}

QStringList presetNames()
{
    QStringList names;
    for (const PresetEntry &entry : kPresets)
        names.append(QString::fromUtf16(entry.name));
    return names;
}

std::optional<Profile> preset(const QString &name)
{
    // The resources live in the static hatpic_core library; registering them explicitly keeps
    // them working for any consumer, whatever its linker does with unreferenced objects.
    static const bool registered = (initPresetResources(), true);
    Q_UNUSED(registered);
    for (const PresetEntry &entry : kPresets) {
        if (name.compare(QString::fromUtf16(entry.name), Qt::CaseInsensitive) != 0)
            continue;
        ProfileReadResult result = readProfile(QString::fromUtf16(entry.path));
        return result.profile;
    }
    return std::nullopt;
}

} // namespace hatpic
