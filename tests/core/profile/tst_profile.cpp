// Tests for profile files (profile.md): reading rules, exact writing, atomic saves, presets.

#include "model/derived.h"
#include "profile/jsonkeys.h"
#include "profile/paramsjson.h"
#include "profile/profile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>
#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::Profile;

// A complete, valid profile document as a JSON object (the spec's example values).
QJsonObject validObject()
{
    return QJsonObject{
        {u"format"_s, u"hatpic-profile"_s},
        {u"version"_s, 1},
        {u"name"_s, u"Test"_s},
        {u"notes"_s, u"free text"_s},
        {u"device"_s, QJsonObject{{u"D_adm"_s, 0.0001},
                                  {u"M_adm"_s, 0.01},
                                  {u"K_min"_s, 0.15},
                                  {u"K_max"_s, 0.4},
                                  {u"N"_s, 0.1},
                                  {u"Q_dz"_s, 0.02},
                                  {u"theta0"_s, 0.0}}},
        {u"host"_s, QJsonObject{{u"mode"_s, u"translation"_s},
                                {u"v_max"_s, 1.0},
                                {u"ref_deadzone"_s, true},
                                {u"tau_limit"_s, 0.44}}},
    };
}

const QJsonValue kRemove(QJsonValue::Undefined);

void setOrRemove(QJsonObject &object, const QString &key, const QJsonValue &value)
{
    if (value.isUndefined())
        object.remove(key);
    else
        object.insert(key, value);
}

QByteArray withTop(const QString &key, const QJsonValue &value)
{
    QJsonObject root = validObject();
    setOrRemove(root, key, value);
    return QJsonDocument(root).toJson();
}

// Sets (or removes) keys inside "device" or "host".
QByteArray withInner(const QString &section, const QJsonObject &changes,
                     const QStringList &removed = {})
{
    QJsonObject root = validObject();
    QJsonObject inner = root.value(section).toObject();
    for (auto it = changes.begin(); it != changes.end(); ++it)
        inner.insert(it.key(), it.value());
    for (const QString &key : removed)
        inner.remove(key);
    root.insert(section, inner);
    return QJsonDocument(root).toJson();
}

QByteArray withDevice(const QString &key, const QJsonValue &value)
{
    return value.isUndefined() ? withInner(u"device"_s, {}, {key})
                               : withInner(u"device"_s, {{key, value}});
}

QByteArray withHost(const QString &key, const QJsonValue &value)
{
    return value.isUndefined() ? withInner(u"host"_s, {}, {key})
                               : withInner(u"host"_s, {{key, value}});
}

bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// What reading back a written number must give, to the bit: the number itself, except that
// −0.0 is written as 0.0 (documented in docs/profile.md).
bool readsBackAs(double read, double written)
{
    return sameBits(read, written == 0.0 ? 0.0 : written);
}

// Every field of a read-back profile identical to the bit to what was written.
bool identical(const Profile &read, const Profile &written)
{
    for (int i = 0; i < hatpic::DeviceParams::kFieldCount; ++i) {
        if (!readsBackAs(read.device.field(i), written.device.field(i)))
            return false;
    }
    return read.name == written.name && read.notes == written.notes &&
           read.host.mode == written.host.mode &&
           read.host.ref_deadzone == written.host.ref_deadzone &&
           readsBackAs(read.host.v_max, written.host.v_max) &&
           readsBackAs(read.host.tau_limit, written.host.tau_limit);
}

// Number of seeded random cases; raise with HATPIC_RANDOM_CASES=100000.
int randomCases()
{
    const int n = qEnvironmentVariableIntValue("HATPIC_RANDOM_CASES");
    return n > 0 ? n : 5000;
}

// Random doubles with full 53-bit mantissas spread over all binary exponents of [lo, hi].
class RandomDoubles
{
public:
    explicit RandomDoubles(std::uint64_t seed) : m_engine(seed) {}

    // Positive value in [lo, hi] (lo > 0); log-uniform exponent, random mantissa.
    double in(double lo, double hi)
    {
        std::uniform_int_distribution<int> exp(std::ilogb(lo), std::ilogb(hi));
        for (;;) {
            const double mantissa =
                std::bit_cast<double>((m_engine() >> 12) | 0x3ff0000000000000ULL); // [1, 2)
            const double v = std::ldexp(mantissa, exp(m_engine));
            if (v >= lo && v <= hi)
                return v;
        }
    }
    // In [0, hi]: sometimes exactly 0, −0.0, the smallest subnormal or hi itself.
    double zeroTo(double hi)
    {
        switch (m_engine() % 10) {
        case 0:
            return 0.0;
        case 1:
            return -0.0;
        case 2:
            return std::numeric_limits<double>::denorm_min();
        case 3:
            return hi;
        default:
            return in(std::numeric_limits<double>::denorm_min(), hi);
        }
    }
    bool coin() { return m_engine() % 2 == 0; }
    std::uint64_t bits() { return m_engine(); }

    QString text()
    {
        static const char16_t *const kPieces[] = {
            u"a", u"Zz", u" ", u"\"", u"\\",     u"/",  u"\n", u"\t", u"\u0001", u"\u001f",
            u"é", u"π",  u"→", u"😀",  u"\u2028", u"{}", u"[",  u",",  u"\u007f", u"0.1"};
        QString out;
        const int count = static_cast<int>(m_engine() % 12);
        for (int i = 0; i < count; ++i)
            out += QString::fromUtf16(kPieces[m_engine() % std::size(kPieces)]);
        return out;
    }

private:
    std::mt19937_64 m_engine;
};

Profile randomValidProfile(RandomDoubles &r)
{
    Profile p;
    p.name = r.text();
    p.notes = r.text();
    p.device.D_adm = r.in(1e-6, 1.0);
    p.device.M_adm = r.in(std::numeric_limits<double>::denorm_min(), 10.0);
    p.device.K_max = r.zeroTo(50.0);
    p.device.K_min = std::abs(p.device.K_max) > 0 ? r.zeroTo(p.device.K_max) : p.device.K_max;
    p.device.N = r.in(std::numeric_limits<double>::denorm_min(), std::numbers::pi / 2);
    do {
        p.device.Q_dz = r.zeroTo(p.device.N);
    } while (!(p.device.Q_dz < p.device.N));
    p.device.theta0 = r.coin() ? r.zeroTo(std::numbers::pi) : -r.zeroTo(std::numbers::pi);
    p.host.v_max = r.in(std::numeric_limits<double>::denorm_min(), 100.0);
    p.host.tau_limit = r.in(std::numeric_limits<double>::denorm_min(), 10.0);
    p.host.mode = r.coin() ? hatpic::ReferenceMode::Translation : hatpic::ReferenceMode::Rotation;
    p.host.ref_deadzone = r.coin();
    // The bridge's limit within that tau_limit (bridge::limitProblem()).
    p.bridge.feedback.limit = std::min(p.bridge.feedback.limit, p.host.tau_limit);
    return p;
}

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

Profile namedDefault(const QString &name)
{
    Profile p;
    p.name = name;
    return p;
}

} // namespace

Q_DECLARE_METATYPE(hatpic::HostParams)

class TestProfile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void presetResourcesLinked();
    void rejects_data();
    void rejects();
    void multipleViolationsAllReported();
    void acceptsBoundaries_data();
    void acceptsBoundaries();
    void hostOptionalWithDefaults_data();
    void hostOptionalWithDefaults();
    void unknownKeysWarnAndAreDropped();
    void duplicateKeysRefused_data();
    void duplicateKeysRefused();
    void notAProfileGetsNoKeyWarnings();
    void nameAndNotesOptional();
    void serializedTextExact();
    void jsonNumberText_data();
    void jsonNumberText();
    void jsonNumberRoundTripAllDoubles();
    void profileRoundTripExact();
    void writeThenRead();
    void writeFailureKeepsExistingFile_data();
    void writeFailureKeepsExistingFile();
    void writeFailureDiskFull_data();
    void writeFailureDiskFull();
    void writeFailureReadOnlyDirectory();
    void readMissingFile();
    void readDirectory();
    void readPipeRefused();
    void readSizeLimit();
    void readEndlessFileStopsAtLimit();
    void presetsLoadAndValidate();
    void presetsFeelAsNamed();
    void presetLookup();
};

// Runs first: the ":/presets" resources must be present in a test executable before any
// profile code runs, which shows CMake linked the static library's resource object.
void TestProfile::presetResourcesLinked()
{
    QVERIFY(QFile::exists(u":/presets/default.json"_s));
    QVERIFY(QFile::exists(u":/presets/soft.json"_s));
    QVERIFY(QFile::exists(u":/presets/notchy.json"_s));
    const std::optional<Profile> soft = hatpic::preset(u"Soft"_s);
    QVERIFY(soft.has_value());
    QCOMPARE(soft->name, u"Soft"_s);
}

void TestProfile::rejects_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QStringList>("errors");

    // Documents that are not profiles at all.
    QTest::newRow("not JSON: unterminated object")
        << QByteArray("{")
        << QStringList{u"not valid JSON: unterminated object at byte offset 1"_s};
    QTest::newRow("not JSON: trailing comma")
        << QByteArray("{\"format\": \"hatpic-profile\",}")
        << QStringList{u"not valid JSON: object is missing after a comma at byte offset 29"_s};
    QTest::newRow("not JSON: empty")
        << QByteArray() << QStringList{u"not valid JSON: illegal value at byte offset 0"_s};
    QTest::newRow("not JSON: number too large")
        << QByteArray("{\"version\": 1e999}")
        << QStringList{u"not valid JSON: illegal number at byte offset 17 (1e999 is beyond the "
                       u"largest double, about 1.8e308)"_s};
    QTest::newRow("not JSON: number too small")
        << QByteArray("{\"version\": -1e-999}")
        << QStringList{u"not valid JSON: illegal number at byte offset 19 (-1e-999 is too close "
                       u"to 0 for a double)"_s};
    QTest::newRow("not JSON: a sign alone")
        << QByteArray("{\"version\": -}")
        << QStringList{u"not valid JSON: illegal number at byte offset 13 (\"-\" is not a number "
                       u"as JSON writes them)"_s};
    QTest::newRow("not an object: array")
        << QByteArray("[1, 2]")
        << QStringList{u"not a profile: the top level must be a JSON object, got an array"_s};
    QTest::newRow("larger than 1 MiB")
        << (QByteArray("{\"format\": \"hatpic-profile\", \"notes\": \"") +
            QByteArray(hatpic::kMaxProfileBytes, 'x') + QByteArray("\"}"))
        << QStringList{
               u"the file is larger than 1 MiB (1048576 bytes), got 1048617 bytes; refused"_s};

    // format and version.
    QTest::newRow("format missing")
        << withTop(u"format"_s, kRemove)
        << QStringList{u"format: missing, must be \"hatpic-profile\""_s};
    QTest::newRow("format wrong")
        << withTop(u"format"_s, u"hatpic-profil"_s)
        << QStringList{u"format: must be \"hatpic-profile\", got \"hatpic-profil\""_s};
    QTest::newRow("format not a string")
        << withTop(u"format"_s, 1) << QStringList{u"format: must be \"hatpic-profile\", got 1"_s};
    QTest::newRow("version missing")
        << withTop(u"version"_s, kRemove) << QStringList{u"version: missing, must be 1"_s};
    QTest::newRow("version newer")
        << withTop(u"version"_s, 2)
        << QStringList{u"version: the file was written by a newer version of HATPIC Tuner "
                       u"(profile version 2); this build reads profile version 1"_s};
    QTest::newRow("version zero") << withTop(u"version"_s, 0)
                                  << QStringList{u"version: must be 1, got 0"_s};
    QTest::newRow("version fractional")
        << withTop(u"version"_s, 1.5) << QStringList{u"version: must be 1, got 1.5"_s};
    QTest::newRow("version a string")
        << withTop(u"version"_s, u"1"_s) << QStringList{u"version: must be 1, got \"1\""_s};
    QTest::newRow("format and version both wrong stop there")
        <<
        [] {
            QJsonObject root = validObject();
            root.insert(u"format"_s, u"other"_s);
            root.insert(u"version"_s, 3);
            root.insert(u"device"_s, 7); // not examined
            return QJsonDocument(root).toJson();
        }()
        << QStringList{u"format: must be \"hatpic-profile\", got \"other\""_s,
                       u"version: the file was written by a newer version of HATPIC Tuner "
                       u"(profile version 3); this build reads profile version 1"_s};

    // name and notes.
    QTest::newRow("name not a string")
        << withTop(u"name"_s, 3) << QStringList{u"name: must be a string, got 3"_s};
    QTest::newRow("notes not a string") << withTop(u"notes"_s, QJsonArray{})
                                        << QStringList{u"notes: must be a string, got an array"_s};

    // device: presence and type.
    QTest::newRow("device missing")
        << withTop(u"device"_s, kRemove)
        << QStringList{u"device: missing, must be an object with D_adm, M_adm, K_min, K_max, N, "
                       u"Q_dz and theta0"_s};
    QTest::newRow("device not an object")
        << withTop(u"device"_s, u"fast"_s)
        << QStringList{u"device: must be an object, got \"fast\""_s};
    for (const QString &key :
         {u"D_adm"_s, u"M_adm"_s, u"K_min"_s, u"K_max"_s, u"N"_s, u"Q_dz"_s, u"theta0"_s}) {
        QTest::addRow("device.%s missing", qPrintable(key))
            << withDevice(key, kRemove)
            << QStringList{u"device."_s + key + u": missing, must be a number"_s};
    }
    QTest::newRow("device value a string")
        << withDevice(u"N"_s, u"0.1"_s)
        << QStringList{u"device.N: must be a number, got \"0.1\""_s};
    QTest::newRow("device value null")
        << withDevice(u"D_adm"_s, QJsonValue::Null)
        << QStringList{u"device.D_adm: must be a number, got null"_s};
    QTest::newRow("device value a bool")
        << withDevice(u"theta0"_s, false)
        << QStringList{u"device.theta0: must be a number, got false"_s};
    QTest::newRow("device value an object")
        << withDevice(u"M_adm"_s, QJsonObject{})
        << QStringList{u"device.M_adm: must be a number, got an object"_s};
    QTest::newRow("device value a long string is shortened")
        << withDevice(u"M_adm"_s, QString(100, u'7'))
        << QStringList{u"device.M_adm: must be a number, got \""_s + QString(64, u'7') +
                       u"… (100 bytes)\""_s};

    // device: every range rule of model.md § 1.
    QTest::newRow("D_adm below 1e-6")
        << withDevice(u"D_adm"_s, 9.99e-7)
        << QStringList{u"device.D_adm: must be ≥ 1e-06, got 9.99e-07"_s};
    QTest::newRow("D_adm above 1")
        << withDevice(u"D_adm"_s, 1.5) << QStringList{u"device.D_adm: must be ≤ 1, got 1.5"_s};
    QTest::newRow("M_adm zero") << withDevice(u"M_adm"_s, 0)
                                << QStringList{u"device.M_adm: must be > 0, got 0"_s};
    QTest::newRow("M_adm above 10")
        << withDevice(u"M_adm"_s, 10.5) << QStringList{u"device.M_adm: must be ≤ 10, got 10.5"_s};
    QTest::newRow("K_min negative")
        << withDevice(u"K_min"_s, -0.1) << QStringList{u"device.K_min: must be ≥ 0, got -0.1"_s};
    QTest::newRow("K_min above K_max (spec example)")
        << withDevice(u"K_min"_s, 0.9)
        << QStringList{u"device.K_min: must be ≤ K_max (0.4), got 0.9"_s};
    QTest::newRow("K_max negative")
        << withDevice(u"K_max"_s, -1)
        << QStringList{u"device.K_min: must be ≤ K_max (-1), got 0.15"_s,
                       u"device.K_max: must be ≥ 0, got -1"_s};
    QTest::newRow("K_max above 50") << withInner(u"device"_s, {{u"K_max"_s, 51}})
                                    << QStringList{u"device.K_max: must be ≤ 50, got 51"_s};
    QTest::newRow("N zero") << withInner(u"device"_s, {{u"N"_s, 0}, {u"Q_dz"_s, 0}})
                            << QStringList{u"device.N: must be > 0, got 0"_s,
                                           u"device.Q_dz: must be < N (0), got 0"_s};
    QTest::newRow("N above pi/2")
        << withDevice(u"N"_s, 1.6)
        << QStringList{u"device.N: must be ≤ π/2 (1.5707963267948966), got 1.6"_s};
    QTest::newRow("Q_dz negative")
        << withDevice(u"Q_dz"_s, -0.01) << QStringList{u"device.Q_dz: must be ≥ 0, got -0.01"_s};
    QTest::newRow("Q_dz equal to N")
        << withDevice(u"Q_dz"_s, 0.1) << QStringList{u"device.Q_dz: must be < N (0.1), got 0.1"_s};
    QTest::newRow("theta0 below -pi")
        << withDevice(u"theta0"_s, -3.2)
        << QStringList{u"device.theta0: must be ≥ −π (-3.141592653589793), got -3.2"_s};
    QTest::newRow("theta0 above pi")
        << withDevice(u"theta0"_s, 4)
        << QStringList{u"device.theta0: must be ≤ π (3.141592653589793), got 4"_s};
    QTest::newRow("cross-field rule skipped against a non-number")
        << withInner(u"device"_s, {{u"K_max"_s, u"big"_s}, {u"K_min"_s, 7}})
        << QStringList{u"device.K_max: must be a number, got \"big\""_s};

    // host.
    QTest::newRow("host not an object") << withTop(u"host"_s, QJsonArray{1})
                                        << QStringList{u"host: must be an object, got an array"_s};
    QTest::newRow("host.mode unknown")
        << withHost(u"mode"_s, u"sideways"_s)
        << QStringList{u"host.mode: must be \"translation\" or \"rotation\", got \"sideways\""_s};
    QTest::newRow("host.mode wrong case")
        << withHost(u"mode"_s, u"Rotation"_s)
        << QStringList{u"host.mode: must be \"translation\" or \"rotation\", got \"Rotation\""_s};
    QTest::newRow("host.mode not a string")
        << withHost(u"mode"_s, 1)
        << QStringList{u"host.mode: must be \"translation\" or \"rotation\", got 1"_s};
    QTest::newRow("host.ref_deadzone not a bool")
        << withHost(u"ref_deadzone"_s, 1)
        << QStringList{u"host.ref_deadzone: must be true or false, got 1"_s};
    QTest::newRow("host.ref_deadzone a string")
        << withHost(u"ref_deadzone"_s, u"true"_s)
        << QStringList{u"host.ref_deadzone: must be true or false, got \"true\""_s};
    QTest::newRow("host.v_max not a number")
        << withHost(u"v_max"_s, u"1"_s)
        << QStringList{u"host.v_max: must be a number, got \"1\""_s};
    QTest::newRow("host.v_max zero")
        << withHost(u"v_max"_s, 0) << QStringList{u"host.v_max: must be > 0, got 0"_s};
    QTest::newRow("host.v_max above 100")
        << withHost(u"v_max"_s, 100.5) << QStringList{u"host.v_max: must be ≤ 100, got 100.5"_s};
    QTest::newRow("host.tau_limit not a number")
        << withHost(u"tau_limit"_s, QJsonValue::Null)
        << QStringList{u"host.tau_limit: must be a number, got null"_s};
    QTest::newRow("host.tau_limit negative")
        << withHost(u"tau_limit"_s, -0.44)
        << QStringList{u"host.tau_limit: must be > 0, got -0.44"_s};
    QTest::newRow("bridge limit above tau_limit")
        << withHost(u"bridge"_s, QJsonObject{{u"limit"_s, 1}})
        << QStringList{u"host.bridge: limit: must be at most the device's tau_limit (0.44 N·m), "
                       u"got 1"_s};
    QTest::newRow("host.tau_limit above 10")
        << withHost(u"tau_limit"_s, 11) << QStringList{u"host.tau_limit: must be ≤ 10, got 11"_s};
}

void TestProfile::rejects()
{
    QFETCH(QByteArray, json);
    QFETCH(QStringList, errors);
    const hatpic::ProfileReadResult result = hatpic::parseProfile(json);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, errors);
}

void TestProfile::multipleViolationsAllReported()
{
    QJsonObject root = validObject();
    root.insert(u"name"_s, false);
    root.insert(u"device"_s, QJsonObject{{u"D_adm"_s, 0},
                                         {u"M_adm"_s, u"x"_s},
                                         {u"K_min"_s, 0.5},
                                         {u"K_max"_s, 0.4},
                                         {u"N"_s, 0.1},
                                         {u"Q_dz"_s, 0.2}});
    root.insert(u"host"_s, QJsonObject{{u"mode"_s, u"x"_s}, {u"v_max"_s, 0}, {u"tau_limit"_s, 99}});
    const auto result = hatpic::parseProfile(QJsonDocument(root).toJson());
    QVERIFY(!result.ok());
    const QStringList expected = {
        u"name: must be a string, got false"_s,
        u"device.M_adm: must be a number, got \"x\""_s,
        u"device.theta0: missing, must be a number"_s,
        u"device.D_adm: must be ≥ 1e-06, got 0"_s,
        u"device.K_min: must be ≤ K_max (0.4), got 0.5"_s,
        u"device.Q_dz: must be < N (0.1), got 0.2"_s,
        u"host.mode: must be \"translation\" or \"rotation\", got \"x\""_s,
        u"host.v_max: must be > 0, got 0"_s,
        u"host.tau_limit: must be ≤ 10, got 99"_s,
    };
    QCOMPARE(result.errors, expected);
}

void TestProfile::acceptsBoundaries_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");

    QTest::newRow("D_adm = 1e-6") << u"D_adm"_s << 1e-6;
    QTest::newRow("D_adm = 1") << u"D_adm"_s << 1.0;
    QTest::newRow("M_adm smallest subnormal")
        << u"M_adm"_s << std::numeric_limits<double>::denorm_min();
    QTest::newRow("M_adm = 10") << u"M_adm"_s << 10.0;
    QTest::newRow("K_min = 0") << u"K_min"_s << 0.0;
    QTest::newRow("K_min = K_max") << u"K_min"_s << 0.4;
    QTest::newRow("N = pi/2") << u"N"_s << std::numbers::pi / 2;
    QTest::newRow("Q_dz = 0") << u"Q_dz"_s << 0.0;
    QTest::newRow("Q_dz just under N") << u"Q_dz"_s << std::nextafter(0.1, 0.0);
    QTest::newRow("theta0 = -pi") << u"theta0"_s << -std::numbers::pi;
    QTest::newRow("theta0 = pi") << u"theta0"_s << std::numbers::pi;
    QTest::newRow("theta0 = -0.0") << u"theta0"_s << -0.0;
}

void TestProfile::acceptsBoundaries()
{
    QFETCH(QString, key);
    QFETCH(double, value);
    // Written by our own writer so the boundary value reaches the reader bit-exactly.
    const std::optional<Profile> base =
        hatpic::parseProfile(QJsonDocument(validObject()).toJson()).profile;
    QVERIFY(base);
    Profile p = *base;
    p.device.setField(hatpic::deviceFieldIndex(key.toStdString()), value);
    const auto result = hatpic::parseProfile(hatpic::serializeProfile(p));
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    const int index = hatpic::deviceFieldIndex(key.toStdString());
    QVERIFY(readsBackAs(result.profile->device.field(index), value));
}

void TestProfile::hostOptionalWithDefaults_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<hatpic::HostParams>("expected");

    const hatpic::HostParams defaults;
    QTest::newRow("host missing") << withTop(u"host"_s, kRemove) << defaults;
    QTest::newRow("host empty") << withTop(u"host"_s, QJsonObject{}) << defaults;
    hatpic::HostParams rotation;
    rotation.mode = hatpic::ReferenceMode::Rotation;
    QTest::newRow("only mode") << withTop(u"host"_s, QJsonObject{{u"mode"_s, u"rotation"_s}})
                               << rotation;
    hatpic::HostParams noHold;
    noHold.ref_deadzone = false;
    QTest::newRow("only ref_deadzone")
        << withTop(u"host"_s, QJsonObject{{u"ref_deadzone"_s, false}}) << noHold;
    hatpic::HostParams fast;
    fast.v_max = 2.5;
    QTest::newRow("only v_max") << withTop(u"host"_s, QJsonObject{{u"v_max"_s, 2.5}}) << fast;
    hatpic::HostParams strong;
    strong.tau_limit = 1.2;
    QTest::newRow("only tau_limit")
        << withTop(u"host"_s, QJsonObject{{u"tau_limit"_s, 1.2}}) << strong;
    hatpic::HostParams all;
    all.mode = hatpic::ReferenceMode::Rotation;
    all.v_max = 100;
    all.ref_deadzone = false;
    all.tau_limit = 10;
    QTest::newRow("all, at upper bounds")
        << withTop(u"host"_s, QJsonObject{{u"mode"_s, u"rotation"_s},
                                          {u"v_max"_s, 100},
                                          {u"ref_deadzone"_s, false},
                                          {u"tau_limit"_s, 10}})
        << all;
}

void TestProfile::hostOptionalWithDefaults()
{
    QFETCH(QByteArray, json);
    QFETCH(hatpic::HostParams, expected);
    const auto result = hatpic::parseProfile(json);
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(result.warnings.isEmpty());
    QVERIFY(result.profile->host == expected);
}

void TestProfile::unknownKeysWarnAndAreDropped()
{
    QJsonObject root = validObject();
    root.insert(u"colour"_s, u"red"_s);
    QJsonObject device = root.value(u"device"_s).toObject();
    device.insert(u"K_mid"_s, 0.3);
    root.insert(u"device"_s, device);
    QJsonObject host = root.value(u"host"_s).toObject();
    host.insert(u"vmax"_s, 2);
    root.insert(u"host"_s, host);

    const auto result = hatpic::parseProfile(QJsonDocument(root).toJson());
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QCOMPARE(result.warnings, (QStringList{u"unknown key \"colour\" ignored"_s,
                                           u"unknown key \"device.K_mid\" ignored"_s,
                                           u"unknown key \"host.vmax\" ignored"_s}));
    const auto plain = hatpic::parseProfile(QJsonDocument(validObject()).toJson());
    QVERIFY(plain.ok());
    QVERIFY(plain.warnings.isEmpty());
    QVERIFY(*result.profile == *plain.profile);
    const QByteArray written = hatpic::serializeProfile(*result.profile);
    QVERIFY(!written.contains("colour"));
    QVERIFY(!written.contains("K_mid"));
    QVERIFY(!written.contains("vmax"));

    // Warnings are reported with errors too.
    device.insert(u"N"_s, -1);
    root.insert(u"device"_s, device);
    const auto refused = hatpic::parseProfile(QJsonDocument(root).toJson());
    QVERIFY(!refused.ok());
    QCOMPARE(refused.warnings.size(), 3);
}

void TestProfile::duplicateKeysRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("key");
    const QByteArray device = R"("device": {"D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.15,
        "K_max": 0.4, "N": 0.1, "Q_dz": 0.02, "theta0": 0.0)";
    QTest::newRow("device field twice")
        << QByteArray(R"({"format": "hatpic-profile", "version": 1, )" + device +
                      R"(, "K_max": 0.9}})")
        << u"device.K_max"_s;
    QTest::newRow("top-level key twice")
        << QByteArray(R"({"format": "hatpic-profile", "version": 1, "name": "a", )" + device +
                      R"(}, "name": "b"})")
        << u"name"_s;
    QTest::newRow("spelt with an escape")
        << QByteArray(R"({"format": "hatpic-profile", "version": 1, )" + device +
                      R"(, "K_max": 0.9}})")
        << u"device.K_max"_s;
    QTest::newRow("unknown key twice, in an array's object")
        << QByteArray(R"({"format": "hatpic-profile", "version": 1, )" + device +
                      "}, \"extra\": [1, {\"a\": 1, \"b\": \"}\\\"{\", \"a\": 2}]}")
        << u"extra[].a"_s;
}

void TestProfile::duplicateKeysRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, key);
    const hatpic::ProfileReadResult result = hatpic::parseProfile(json);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, QStringList{u"duplicate key \""_s + key +
                                        u"\": a key may appear once (which value was meant?)"_s});
    // The same keys once each (same names in different objects) are fine.
    QVERIFY(hatpic::firstDuplicateKey(
                "{\"a\": {\"x\": 1}, \"b\": {\"x\": 1}, \"c\": [{\"x\": 1}, {\"x\": 2}], "
                "\"s\": \"a\\\"a\"}")
                .isEmpty());
}

void TestProfile::notAProfileGetsNoKeyWarnings()
{
    const hatpic::ProfileReadResult result =
        hatpic::parseProfile(R"({"format": "something-else", "version": 1, "colour": "red"})");
    QVERIFY(!result.ok());
    QCOMPARE(result.errors.size(), 1);
    QVERIFY2(result.errors.first().startsWith(u"format:"_s), qPrintable(result.errors.first()));
    QCOMPARE(result.warnings, QStringList());
}

void TestProfile::nameAndNotesOptional()
{
    QJsonObject root = validObject();
    root.remove(u"name"_s);
    root.remove(u"notes"_s);
    const auto result = hatpic::parseProfile(QJsonDocument(root).toJson());
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(result.profile->name.isEmpty());
    QVERIFY(result.profile->notes.isEmpty());
}

void TestProfile::serializedTextExact()
{
    Profile p;
    p.name = u"Default"_s;
    p.notes = u"free text"_s;
    const QByteArray expected = "{\n"
                                "  \"format\": \"hatpic-profile\",\n"
                                "  \"version\": 1,\n"
                                "  \"name\": \"Default\",\n"
                                "  \"notes\": \"free text\",\n"
                                "  \"device\": {\n"
                                "    \"D_adm\": 0.0001,\n"
                                "    \"M_adm\": 0.01,\n"
                                "    \"K_min\": 0.15,\n"
                                "    \"K_max\": 0.4,\n"
                                "    \"N\": 0.1,\n"
                                "    \"Q_dz\": 0.02,\n"
                                "    \"theta0\": 0.0\n"
                                "  },\n"
                                "  \"host\": {\n"
                                "    \"mode\": \"translation\",\n"
                                "    \"v_max\": 1.0,\n"
                                "    \"ref_deadzone\": true,\n"
                                "    \"tau_limit\": 0.44\n"
                                "  }\n"
                                "}\n";
    QCOMPARE(hatpic::serializeProfile(p), expected);

    // Strings are escaped as JSON requires; everything else is plain UTF-8.
    p.name = u"a\"b\\c/d\né\u0001😀"_s;
    p.notes.clear();
    p.host.mode = hatpic::ReferenceMode::Rotation;
    p.host.ref_deadzone = false;
    const QByteArray text = hatpic::serializeProfile(p);
    QVERIFY(text.contains("  \"name\": \"a\\\"b\\\\c/d\\n\xc3\xa9\\u0001\xf0\x9f\x98\x80\",\n"));
    QVERIFY(text.contains("  \"notes\": \"\",\n"));
    QVERIFY(text.contains("    \"mode\": \"rotation\",\n"));
    QVERIFY(text.contains("    \"ref_deadzone\": false,\n"));
}

void TestProfile::jsonNumberText_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QByteArray>("text");

    QTest::newRow("zero") << 0.0 << QByteArray("0.0");
    QTest::newRow("negative zero is written as zero") << -0.0 << QByteArray("0.0");
    QTest::newRow("one") << 1.0 << QByteArray("1.0");
    QTest::newRow("minus forty") << -40.0 << QByteArray("-40.0");
    QTest::newRow("0.44") << 0.44 << QByteArray("0.44");
    QTest::newRow("0.0001") << 0.0001 << QByteArray("0.0001");
    QTest::newRow("1e-5 still fixed") << 1e-5 << QByteArray("0.00001");
    QTest::newRow("1e-6 exponent") << 1e-6 << QByteArray("1e-6");
    QTest::newRow("pi") << std::numbers::pi << QByteArray("3.141592653589793");
    QTest::newRow("123.456") << 123.456 << QByteArray("123.456");
    QTest::newRow("1e15 fixed") << 1e15 << QByteArray("1000000000000000.0");
    QTest::newRow("1e16 exponent") << 1e16 << QByteArray("1e16");
    QTest::newRow("-1.5e300") << -1.5e300 << QByteArray("-1.5e300");
    QTest::newRow("smallest subnormal")
        << std::numeric_limits<double>::denorm_min() << QByteArray("5e-324");
    QTest::newRow("largest") << std::numeric_limits<double>::max()
                             << QByteArray("1.7976931348623157e308");
    QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << QByteArray("null");
    QTest::newRow("inf") << std::numeric_limits<double>::infinity() << QByteArray("null");
}

void TestProfile::jsonNumberText()
{
    QFETCH(double, value);
    QFETCH(QByteArray, text);
    QCOMPARE(hatpic::jsonNumber(value), text);
}

// The writer's numbers read back bit-identical through Qt's JSON reader, over all finite doubles.
void TestProfile::jsonNumberRoundTripAllDoubles()
{
    RandomDoubles r(20240611);
    const int cases = randomCases() * 4;
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  9007199254740992.0,
                                  9007199254740994.0,
                                  1e15,
                                  1e16,
                                  123456789012345680000.0,
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::lowest(),
                                  std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::denorm_min()};
    while (values.size() < static_cast<std::size_t>(cases)) {
        const double v = std::bit_cast<double>(r.bits());
        if (std::isfinite(v))
            values.push_back(v);
    }
    for (double v : values) {
        const QByteArray text = hatpic::jsonNumber(v);
        QVERIFY2(text.contains('.') || text.contains('e'), text.constData());
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson("[" + text + "]", &error);
        QVERIFY2(error.error == QJsonParseError::NoError, text.constData());
        const double back = doc.array().at(0).toDouble();
        QVERIFY2(readsBackAs(back, v), text.constData());
    }
}

void TestProfile::profileRoundTripExact()
{
    RandomDoubles r(7);
    const int cases = randomCases();
    for (int i = 0; i < cases; ++i) {
        const Profile p = randomValidProfile(r);
        QVERIFY(hatpic::validate(p.device).empty());
        QVERIFY(hatpic::validate(p.host).empty());
        const QByteArray text = hatpic::serializeProfile(p);
        const auto result = hatpic::parseProfile(text);
        QVERIFY2(result.ok(),
                 qPrintable(result.errors.join(u'\n') + u'\n' + QString::fromUtf8(text)));
        QVERIFY(result.warnings.isEmpty());
        QVERIFY2(identical(*result.profile, p), text.constData());
        // Writing what was read gives the same bytes.
        QCOMPARE(hatpic::serializeProfile(*result.profile), text);
    }
}

void TestProfile::writeThenRead()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"tuning.json"_s);
    Profile p = namedDefault(u"Mine"_s);
    p.device.K_max = 0.7;
    p.device.theta0 = -0.25;
    QCOMPARE(hatpic::writeProfile(p, path), QString());
    QCOMPARE(fileBytes(path), hatpic::serializeProfile(p));
    const auto result = hatpic::readProfile(path);
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(identical(*result.profile, p));

    // Overwriting replaces the whole content.
    p.name = u"x"_s;
    QCOMPARE(hatpic::writeProfile(p, path), QString());
    QCOMPARE(fileBytes(path), hatpic::serializeProfile(p));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"tuning.json"_s});
}

void TestProfile::writeFailureKeepsExistingFile_data()
{
    QTest::addColumn<QString>("target"); // relative to the temporary directory
    QTest::addColumn<bool>("invalidProfile");
    QTest::addColumn<QString>("error"); // with "%1" for the absolute target path

    QTest::newRow("path is a directory")
        << u"adir"_s << false << u"cannot write profile \"%1\": Filename refers to a directory"_s;
    QTest::newRow("parent directory missing")
        << u"missing/good.json"_s << false
        << u"cannot write profile \"%1\": No such file or directory"_s;
    QTest::newRow("invalid profile refused")
        << u"good.json"_s << true
        << u"refusing to write an invalid profile to \"%1\": device.K_min: must be ≤ K_max "
           u"(0.4), got 0.9; host.v_max: must be > 0, got -1"_s;
}

void TestProfile::writeFailureKeepsExistingFile()
{
    QFETCH(QString, target);
    QFETCH(bool, invalidProfile);
    QFETCH(QString, error);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(u"adir"_s));
    const QString good = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), good), QString());
    const QByteArray before = fileBytes(good);
    QVERIFY(!before.isEmpty());

    Profile p = namedDefault(u"Other"_s);
    if (invalidProfile) {
        p.device.K_min = 0.9;
        p.host.v_max = -1;
    }
    const QString path = dir.filePath(target);
    QCOMPARE(hatpic::writeProfile(p, path), error.arg(path));
    QCOMPARE(fileBytes(good), before);
    QVERIFY(QFileInfo(dir.filePath(u"adir"_s)).isDir());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"good.json"_s});
}

// A write that fails half-way (here: the file-size limit, as on a full disk) leaves the old
// file byte-identical and no temporary file behind. Works as root too.
void TestProfile::writeFailureDiskFull_data()
{
    QTest::addColumn<int>("notesSize");
    // QFileDevice buffers small writes: the first row fails only when commit() flushes, the
    // second already in write(), which bypasses the 16 KiB buffer for large blocks.
    QTest::newRow("fails on commit") << 4000;
    QTest::newRow("fails on write") << 40000;
}

void TestProfile::writeFailureDiskFull()
{
    QFETCH(int, notesSize);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), path), QString());
    const QByteArray before = fileBytes(path);

    Profile big = namedDefault(u"Big"_s);
    big.notes = QString(notesSize, u'n');

    rlimit old{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = old;
    limited.rlim_cur = 1000; // bytes: less than the profile being written
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &limited), 0);
    const QString error = hatpic::writeProfile(big, path);
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &old), 0);
    std::signal(SIGXFSZ, oldHandler);

    QCOMPARE(error, u"cannot write profile \""_s + path + u"\": File too large"_s);
    QCOMPARE(fileBytes(path), before);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"good.json"_s});
}

void TestProfile::writeFailureReadOnlyDirectory()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), path), QString());
    const QByteArray before = fileBytes(path);
    QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
    const bool canStillCreate = QFile(dir.filePath(u"probe"_s)).open(QIODevice::WriteOnly);
    if (canStillCreate) {
        QFile::remove(dir.filePath(u"probe"_s));
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QSKIP("permissions are not enforced for this user (root); see writeFailureDiskFull");
    }
    const QString error = hatpic::writeProfile(namedDefault(u"Other"_s), path);
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(error.startsWith(u"cannot write profile \""_s + path + u"\": "_s));
    QCOMPARE(fileBytes(path), before);
}

void TestProfile::readMissingFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"nowhere.json"_s);
    const auto result = hatpic::readProfile(path);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors,
             QStringList{u"cannot open profile \""_s + path + u"\": No such file or directory"_s});
}

void TestProfile::readDirectory()
{
    QTemporaryDir dir;
    const auto result = hatpic::readProfile(dir.path());
    QVERIFY(!result.ok());
    QCOMPARE(result.errors,
             QStringList{u"profile \""_s + dir.path() + u"\" is a folder, not a file"_s});
}

// A pipe would block the open until a writer comes: it is refused before (issue 21).
void TestProfile::readPipeRefused()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"fifo"_s);
    QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    const auto result = hatpic::readProfile(path);
    QCOMPARE(result.errors, QStringList{u"profile \""_s + path +
                                        u"\" is not a regular file (a device or a pipe); "
                                        u"refused"_s});
}

void TestProfile::readSizeLimit()
{
    QTemporaryDir dir;
    const QByteArray text = hatpic::serializeProfile(namedDefault(u"Padded"_s));
    const QString path = dir.filePath(u"p.json"_s);

    // Exactly 1 MiB (whitespace padding is valid JSON) is accepted.
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(text);
        file.write(QByteArray(hatpic::kMaxProfileBytes - text.size(), ' '));
    }
    QCOMPARE(QFileInfo(path).size(), hatpic::kMaxProfileBytes);
    const auto accepted = hatpic::readProfile(path);
    QVERIFY2(accepted.ok(), qPrintable(accepted.errors.join(u'\n')));

    // One byte more is refused.
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::Append));
        file.write(" ");
    }
    const auto refused = hatpic::readProfile(path);
    QVERIFY(!refused.ok());
    QCOMPARE(refused.errors, QStringList{u"profile \""_s + path +
                                         u"\" is larger than 1 MiB (1048576 bytes), got "
                                         u"1048577 bytes; refused"_s});
}

// /dev/zero never ends and reports size 0: it is not read at all.
void TestProfile::readEndlessFileStopsAtLimit()
{
    if (!QFileInfo::exists(u"/dev/zero"_s))
        QSKIP("no /dev/zero");
    const auto result = hatpic::readProfile(u"/dev/zero"_s);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, QStringList{u"profile \"/dev/zero\" is not a regular file (a device "
                                        u"or a pipe); refused"_s});
}

void TestProfile::presetsLoadAndValidate()
{
    QCOMPARE(hatpic::presetNames(),
             (QStringList{u"Default"_s, u"Soft"_s, u"Notchy"_s, u"Detents"_s, u"Walled"_s}));
    for (const QString &name : hatpic::presetNames()) {
        const QString path = u":/presets/"_s + name.toLower() + u".json"_s;
        const auto result = hatpic::readProfile(path);
        QVERIFY2(result.ok(), qPrintable(name + u": "_s + result.errors.join(u'\n')));
        QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
        QCOMPARE(result.profile->name, name);
        QVERIFY(!result.profile->notes.isEmpty());
        QVERIFY(hatpic::validate(result.profile->device).empty());
        QVERIFY(hatpic::validate(result.profile->host).empty());
        // The shipped file is exactly what the writer produces for it.
        QCOMPARE(fileBytes(path), hatpic::serializeProfile(*result.profile));
        const std::optional<Profile> viaPreset = hatpic::preset(name);
        QVERIFY(viaPreset);
        QVERIFY(identical(*viaPreset, *result.profile));
    }
    // "Default" is the spec's defaults.
    const Profile def = *hatpic::preset(u"Default"_s);
    QVERIFY(def.device == hatpic::DeviceParams{});
    QVERIFY(def.host == hatpic::HostParams{});
}

// The figures docs/profile.md quotes for each preset.
void TestProfile::presetsFeelAsNamed()
{
    const Profile def = *hatpic::preset(u"Default"_s);
    const Profile soft = *hatpic::preset(u"Soft"_s);
    const Profile notchy = *hatpic::preset(u"Notchy"_s);
    const auto fDef = hatpic::deriveFigures(def.device, def.host);
    const auto fSoft = hatpic::deriveFigures(soft.device, soft.host);
    const auto fNotchy = hatpic::deriveFigures(notchy.device, notchy.host);

    for (const auto &f : {fDef, fSoft, fNotchy}) {
        QVERIFY(!f.saturates());
        QVERIFY(!f.rings());
        QCOMPARE(f.tauLimit, 0.44);
    }
    // Soft: lower stiffness everywhere, lower natural frequency, at least critically damped.
    QVERIFY(soft.device.K_max < def.device.K_max);
    QVERIFY(soft.device.K_min < def.device.K_min);
    QVERIFY(fSoft.omega_n < fDef.omega_n);
    QVERIFY(fSoft.zeta >= 1.0);
    QVERIFY(fSoft.peakTauRec < fDef.peakTauRec);
    // Notchy: a much larger K_max/K_min ratio, a wider notch, a bigger notch step — but not
    // so big that the knob chatters at the dead-zone edge (issue 12: a step of 0.06 N·m did,
    // under the simulator's gentle hand; tst_chatterdetector runs every preset against it).
    QVERIFY(notchy.device.K_max / notchy.device.K_min >= 10.0);
    QVERIFY(notchy.device.K_max / notchy.device.K_min > 2 * def.device.K_max / def.device.K_min);
    QVERIFY(notchy.device.N > def.device.N);
    QVERIFY(notchy.device.K_max * notchy.device.Q_dz > 1.25 * def.device.K_max * def.device.Q_dz);
    QVERIFY(fNotchy.zeta > 0.5);

    qInfo("preset   omega_n[rad/s]  zeta   T[s]     peak|tau_rec|[N·m] at[rad]  notch step[N·m]");
    for (const Profile *p : {&def, &soft, &notchy}) {
        const auto f = hatpic::deriveFigures(p->device, p->host);
        qInfo("%-8s %8.2f %10.3f %8.4f %10.4f %12.4f %10.4f", qPrintable(p->name), f.omega_n,
              f.zeta, f.timeConstant, f.peakTauRec, f.peakAngle, p->device.K_max * p->device.Q_dz);
    }
}

void TestProfile::presetLookup()
{
    QVERIFY(hatpic::preset(u"soft"_s).has_value());
    QCOMPARE(hatpic::preset(u"NOTCHY"_s)->name, u"Notchy"_s);
    QVERIFY(!hatpic::preset(u"Hard"_s).has_value());
    QVERIFY(!hatpic::preset(QString()).has_value());
}

QTEST_GUILESS_MAIN(TestProfile)
#include "tst_profile.moc"
