// Tests for reading profile files (profile.md § Reading): what is refused and with which
// words, every violation reported, boundaries accepted, the host section's defaults, unknown
// keys warned about and dropped, duplicate keys refused, optional name and notes.

#include "profile/jsonkeys.h"
#include "profile/paramsjson.h"
#include "profile/profile.h"
#include "readback.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <numbers>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::Profile;
using hatpic::test::readsBackAs;

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

} // namespace

Q_DECLARE_METATYPE(hatpic::HostParams)

class TestProfileRules : public QObject
{
    Q_OBJECT

private Q_SLOTS:
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
};

void TestProfileRules::rejects_data()
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

void TestProfileRules::rejects()
{
    QFETCH(QByteArray, json);
    QFETCH(QStringList, errors);
    const hatpic::ProfileReadResult result = hatpic::parseProfile(json);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, errors);
}

void TestProfileRules::multipleViolationsAllReported()
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

void TestProfileRules::acceptsBoundaries_data()
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

void TestProfileRules::acceptsBoundaries()
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

void TestProfileRules::hostOptionalWithDefaults_data()
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

void TestProfileRules::hostOptionalWithDefaults()
{
    QFETCH(QByteArray, json);
    QFETCH(hatpic::HostParams, expected);
    const auto result = hatpic::parseProfile(json);
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(result.warnings.isEmpty());
    QVERIFY(result.profile->host == expected);
}

void TestProfileRules::unknownKeysWarnAndAreDropped()
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

void TestProfileRules::duplicateKeysRefused_data()
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

void TestProfileRules::duplicateKeysRefused()
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

void TestProfileRules::notAProfileGetsNoKeyWarnings()
{
    const hatpic::ProfileReadResult result =
        hatpic::parseProfile(R"({"format": "something-else", "version": 1, "colour": "red"})");
    QVERIFY(!result.ok());
    QCOMPARE(result.errors.size(), 1);
    QVERIFY2(result.errors.first().startsWith(u"format:"_s), qPrintable(result.errors.first()));
    QCOMPARE(result.warnings, QStringList());
}

void TestProfileRules::nameAndNotesOptional()
{
    QJsonObject root = validObject();
    root.remove(u"name"_s);
    root.remove(u"notes"_s);
    const auto result = hatpic::parseProfile(QJsonDocument(root).toJson());
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(result.profile->name.isEmpty());
    QVERIFY(result.profile->notes.isEmpty());
}

QTEST_GUILESS_MAIN(TestProfileRules)
#include "tst_profilerules.moc"
