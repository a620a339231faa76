#include "profile.h"

#include "bridgejson.h"
#include "jsonfile.h"
#include "profile/paramsjson.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QSaveFile>

#include <array>
#include <cerrno>
#include <cmath>
#include <string_view>

// Q_INIT_RESOURCE must be used outside any namespace.
static void initPresetResources()
{
    Q_INIT_RESOURCE(presets);
}

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

const QString kFormat = QStringLiteral("hatpic-profile");

struct PresetEntry
{
    const char16_t *name;
    const char16_t *path;
};

constexpr std::array<PresetEntry, 5> kPresets = {{
    {u"Default", u"default.json"},
    {u"Soft", u"soft.json"},
    {u"Notchy", u"notchy.json"},
    {u"Detents", u"detents.json"},
    {u"Walled", u"walled.json"},
}};

const QString kEffectsKey = QStringLiteral("effects");
const QString kPassivityKey = QStringLiteral("passivity");

// Checks format and version. Returns false when the document is not a profile this build can
// read, in which case nothing else is examined.
bool checkHeader(const QJsonObject &root, QStringList &errors)
{
    const QJsonValue format = root.value(u"format");
    if (format.isUndefined())
        errors.append(u"format: missing, must be \"" + kFormat + u'"');
    else if (format.toString() != kFormat)
        errors.append(u"format: must be \"" + kFormat + u"\", got " + jsonValueText(format));

    const QJsonValue version = root.value(u"version");
    const QString versionText = QString::number(kProfileVersion);
    const double v = version.toDouble(std::nan(""));
    const bool integral = version.isDouble() && std::isfinite(v) && v == std::floor(v);
    if (version.isUndefined())
        errors.append(u"version: missing, must be " + versionText);
    else if (integral && v > kProfileVersion)
        errors.append(u"version: the file was written by a newer version of HATPIC Tuner "
                      u"(profile version " +
                      QString::fromStdString(formatNumber(v)) +
                      u"); this build reads profile version " + versionText);
    else if (!integral || v != kProfileVersion)
        errors.append(u"version: must be " + versionText + u", got " + jsonValueText(version));
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
        errors.append(key + u": must be a string, got " + jsonValueText(value));
}

void readDevice(const QJsonObject &root, DeviceParams &device, QStringList &errors,
                QStringList &warnings)
{
    const QJsonValue deviceValue = root.value(u"device");
    if (deviceValue.isUndefined()) {
        QString names;
        for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
            names += i == 0 ? u""_s : i + 1 < DeviceParams::kFieldCount ? u", "_s : u" and "_s;
            const std::string_view name = deviceFieldName(i);
            names += QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
        }
        errors.append(u"device: missing, must be an object with " + names);
        return;
    }
    if (!deviceValue.isObject()) {
        errors.append(u"device: must be an object, got " + jsonValueText(deviceValue));
        return;
    }
    // Missing or non-number fields hold NaN: their own "must be finite" is not repeated, and
    // validate() skips cross-field rules against them.
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        device.setField(i, std::nan(""));
    const auto present = readDeviceParams(deviceValue.toObject(), QStringLiteral("device."), device,
                                          errors, &warnings, {kEffectsKey, kPassivityKey});

    // Range and cross-field rules.
    for (const Violation &v : validate(device)) {
        if (v.index >= 0 && present[static_cast<std::size_t>(v.index)])
            errors.append(u"device." + QString::fromStdString(v.message()));
    }
}

// An optional block of `device` (effects, passivity): absent, it keeps its defaults, and so does
// each key it lacks; a field present that breaks a rule of `check` is an error naming it.
template<typename Block, typename Read, typename Check>
void readDeviceBlock(const QJsonObject &root, const QString &key, Block &block, Read read,
                     Check check, QStringList &errors, QStringList &warnings)
{
    const QJsonValue value = root.value(u"device").toObject().value(key);
    if (value.isUndefined())
        return;
    const QString prefix = u"device."_s + key + u'.';
    if (!value.isObject()) {
        errors.append(u"device."_s + key + u": must be an object, got " + jsonValueText(value));
        return;
    }
    const auto present = read(value.toObject(), prefix, block, errors, warnings);
    for (const Violation &v : check(block)) {
        if (v.index >= 0 && present[static_cast<std::size_t>(v.index)])
            errors.append(prefix + QString::fromStdString(v.message()));
    }
}

void readHost(const QJsonObject &root, HostParams &host, bridge::BridgeSettings &bridge,
              QStringList &errors, QStringList &warnings)
{
    const QJsonValue hostValue = root.value(u"host");
    if (hostValue.isUndefined())
        return;
    if (!hostValue.isObject()) {
        errors.append(u"host: must be an object, got " + jsonValueText(hostValue));
        return;
    }
    const QString bridgeKey = QString::fromLatin1(kHostBridgeKey);
    const QJsonObject hostObject = hostValue.toObject();
    const QStringList nonNumbers =
        readHostParams(hostObject, QStringLiteral("host."), host, errors, &warnings, {bridgeKey});
    // The bridge's settings: optional, each missing key keeps its default.
    if (const QJsonValue value = hostObject.value(bridgeKey); value.isObject())
        readBridgeSettings(value.toObject(), u"host."_s + bridgeKey + u'.', bridge, errors,
                           warnings);
    else if (!value.isUndefined())
        errors.append(u"host."_s + bridgeKey + u": must be an object, got " + jsonValueText(value));
    for (const Violation &v : validate(host)) {
        const QString message = QString::fromStdString(v.message());
        if (!nonNumbers.contains(QString::fromStdString(v.field)))
            errors.append(u"host." + message);
    }
    if (const std::string problem = bridge::limitProblem(bridge.feedback, host.tau_limit);
        !problem.empty())
        errors.append(u"host."_s + bridgeKey + u": " + QString::fromStdString(problem));
}

// The host object; its bridge object only when a setting differs from its default, so the
// files of everyone who never touches the bridge stay as they were.
QByteArray hostJson(const Profile &profile)
{
    JsonObjectWriter writer = hostParamsWriter(profile.host, 2);
    const bridge::BridgeSettings defaults =
        bridge::withNetworkOf(bridge::BridgeSettings(), profile.bridge);
    if (profile.bridge != defaults)
        writer.add(kHostBridgeKey, bridgeSettingsJson(profile.bridge, 4));
    return writer.text();
}

// The device object; its effects object when `always` names it or when the block travels
// differently from the defaults (a device's read-back of them is ±π moved inside by one
// float), so profiles without effects stay as they were.
QByteArray deviceJson(const Profile &profile, ProfileBlocks always)
{
    JsonObjectWriter writer = deviceParamsWriter(profile.device, 2);
    const double tauLimit = profile.host.tau_limit;
    if (always.effects ||
        roundedForWire(profile.effects, tauLimit) != roundedForWire(EffectParams{}, tauLimit))
        writer.add("effects", effectParamsJson(profile.effects, 4));
    // The same for the passivity block: written once it differs from the defaults.
    if (always.passivity || !sameOnWire(profile.passivity, PassivityParams{}))
        writer.add("passivity", passivityParamsJson(profile.passivity, 4));
    return writer.text();
}

} // namespace

ProfileReadResult parseProfile(const QByteArray &json)
{
    ProfileReadResult result;
    if (json.size() > kMaxProfileBytes) {
        result.errors.append(u"the file is larger than " + byteLimitText(kMaxProfileBytes) + u" (" +
                             QString::number(kMaxProfileBytes) + u" bytes), got " +
                             QString::number(json.size()) + u" bytes; refused");
        return result;
    }

    const JsonObjectRead read = parseJsonObject(json);
    if (!read.object) {
        result.errors.append(read.notAnObject ? u"not a profile: " + read.error : read.error);
        return result;
    }
    const QJsonObject &root = *read.object;
    // Not a profile at all: its error alone, no word about keys a profile does not have.
    if (!checkHeader(root, result.errors))
        return result;

    warnUnknownKeys(root,
                    {QStringLiteral("format"), QStringLiteral("version"), QStringLiteral("name"),
                     QStringLiteral("notes"), QStringLiteral("device"), QStringLiteral("host")},
                    QString(), result.warnings);

    Profile profile;
    readOptionalString(root, u"name", profile.name, result.errors);
    readOptionalString(root, u"notes", profile.notes, result.errors);
    readDevice(root, profile.device, result.errors, result.warnings);
    readHost(root, profile.host, profile.bridge, result.errors, result.warnings);
    // The effects against the profile's tau_limit (host), the limit the detents may not exceed.
    const double tauLimit = profile.host.tau_limit;
    readDeviceBlock(
        root, kEffectsKey, profile.effects, readEffectParams,
        [tauLimit](const EffectParams &e) { return validate(e, tauLimit); }, result.errors,
        result.warnings);
    readDeviceBlock(
        root, kPassivityKey, profile.passivity, readPassivityParams,
        [](const PassivityParams &p) { return validate(p); }, result.errors, result.warnings);

    if (result.errors.isEmpty())
        result.profile = profile;
    return result;
}

ProfileReadResult readProfile(const QString &path)
{
    ProfileReadResult result;
    QString error;
    const std::optional<QByteArray> data =
        readBoundedFile(path, QStringLiteral("profile"), kMaxProfileBytes, &error);
    if (!data) {
        result.errors.append(error);
        return result;
    }
    return parseProfile(*data);
}

QByteArray serializeProfile(const Profile &profile, ProfileBlocks always)
{
    return JsonObjectWriter(0)
               .add("format", jsonString(kFormat))
               .add("version", QByteArray::number(kProfileVersion))
               .add("name", jsonString(profile.name))
               .add("notes", jsonString(profile.notes))
               .add("device", deviceJson(profile, always))
               .add("host", hostJson(profile))
               .text() +
           '\n';
}

QString writeProfile(const Profile &profile, const QString &path)
{
    // A profile that could not be read back is not written; the file on disk stays as it was.
    QStringList problems;
    for (const Violation &v : validate(profile.device))
        problems.append(u"device." + QString::fromStdString(v.message()));
    for (const Violation &v : validate(profile.host))
        problems.append(u"host." + QString::fromStdString(v.message()));
    for (const Violation &v : validate(profile.effects, profile.host.tau_limit))
        problems.append(u"device.effects." + QString::fromStdString(v.message()));
    for (const Violation &v : validate(profile.passivity))
        problems.append(u"device.passivity." + QString::fromStdString(v.message()));
    for (const std::string &problem : bridge::validate(profile.bridge))
        problems.append(u"host.bridge: " + QString::fromStdString(problem));
    if (const std::string problem =
            bridge::limitProblem(profile.bridge.feedback, profile.host.tau_limit);
        !problem.empty())
        problems.append(u"host.bridge: " + QString::fromStdString(problem));
    if (!problems.isEmpty())
        return u"refusing to write an invalid profile to \"" + path + u"\": " +
               problems.join(u"; ");

    // Nor one that reads would refuse: larger than a profile may be (long notes, say, grown by
    // a save), or anything else parseProfile() would not take back.
    const QByteArray data = serializeProfile(profile);
    if (data.size() > kMaxProfileBytes)
        return u"refusing to write profile \"" + path + u"\": it would be " +
               QString::number(data.size()) + u" bytes, more than the " +
               byteLimitText(kMaxProfileBytes) + u" a profile may be, so it could not be read " +
               u"back (shorten its notes or name)";
    if (const ProfileReadResult back = parseProfile(data); !back.ok())
        return u"refusing to write profile \"" + path + u"\": it would not read back (" +
               back.errors.join(u"; ") + u')';

    if (const QString why = replaceFileContents(path, data); !why.isEmpty())
        return u"cannot write profile \"" + path + u"\": " + why;
    return {};
}

QStringList presetNames()
{
    QStringList names;
    for (const PresetEntry &entry : kPresets)
        names.append(QString::fromUtf16(entry.name));
    return names;
}

QStringList presetDirectories()
{
    // The resources live in the static hatpic_profile library; registering them explicitly keeps
    // them working for any consumer, whatever its linker does with unreferenced objects.
    static const bool registered = (initPresetResources(), true);
    Q_UNUSED(registered);
    QStringList dirs;
    if (QCoreApplication::instance()) {
        dirs.append(QDir::cleanPath(QCoreApplication::applicationDirPath() + u'/' +
                                    QStringLiteral(HATPIC_PRESETS_FROM_BINDIR)));
    }
    dirs.append(u":/presets"_s);
    return dirs;
}

QString presetFile(const QString &name, const QStringList &dirs)
{
    for (const PresetEntry &entry : kPresets) {
        if (name.compare(QString::fromUtf16(entry.name), Qt::CaseInsensitive) != 0)
            continue;
        for (const QString &dir : dirs) {
            const QString path = QDir(dir).filePath(QString::fromUtf16(entry.path));
            if (QFileInfo::exists(path))
                return path;
        }
    }
    return {};
}

std::optional<Profile> preset(const QString &name)
{
    const QString path = presetFile(name);
    if (path.isEmpty())
        return std::nullopt;
    return readProfile(path).profile;
}

} // namespace hatpic
