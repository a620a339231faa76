// Tests for the bridge object of a profile's host block (profile.md): defaults when absent,
// exact round trip, the rules of bridgesettings.h reported with the block's name, unknown keys.

#include "profile/bridgejson.h"
#include "profile/profile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::Profile;
using hatpic::bridge::BridgeSettings;

// A valid profile document; with `bridge` unless it is undefined.
QByteArray document(const QJsonValue &bridge = QJsonValue(QJsonValue::Undefined))
{
    QJsonObject host{{u"mode"_s, u"translation"_s}, {u"v_max"_s, 1.0}};
    if (!bridge.isUndefined())
        host.insert(u"bridge"_s, bridge);
    const QJsonObject root{
        {u"format"_s, u"hatpic-profile"_s},
        {u"version"_s, 1},
        {u"device"_s, QJsonObject{{u"D_adm"_s, 0.0001},
                                  {u"M_adm"_s, 0.01},
                                  {u"K_min"_s, 0.15},
                                  {u"K_max"_s, 0.4},
                                  {u"N"_s, 0.1},
                                  {u"Q_dz"_s, 0.02},
                                  {u"theta0"_s, 0.0}}},
        {u"host"_s, host},
    };
    return QJsonDocument(root).toJson();
}

// Every setting a profile keeps, away from its default.
BridgeSettings changedSettings()
{
    BridgeSettings s;
    s.topics.jointStates = "/arm/joint_states";
    s.topics.twist = "";
    s.topics.twistUnstamped = "/haptic_twist";
    s.topics.pose = "mavros/setpoint_position/local";
    s.topics.feedback = "/arm/feedback";
    s.topics.wrench = "/arm/wrench";
    s.topics.wrenchUnstamped = "/arm/wrench_raw";
    s.publishRateHz = 250.5;
    s.frameId = "map \"quoted\"";
    s.jointName = "knob_2";
    s.referenceAxis = hatpic::bridge::Component{true, 1};
    s.poseOrigin = {0.1, -2.5e-7, 0.5};
    s.feedback.component = hatpic::bridge::Component{true, 2};
    s.feedback.gain = -0.3333333333333333;
    s.feedback.limit = 0.2;
    s.feedback.staleAfter = 0.25;
    s.qos = hatpic::bridge::QosProfile::BestEffort;
    s.depth = 3;
    return s;
}

} // namespace

class TestProfileBridge : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void absentMeansDefaults();
    void defaultsAreNotWritten();
    void roundTripExact();
    void exactText();
    void missingKeysKeepDefaults();
    void rejects_data();
    void rejects();
    void unknownKeysWarn();
    void writeRefusesInvalid();
};

void TestProfileBridge::absentMeansDefaults()
{
    const auto result = hatpic::parseProfile(document());
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(result.warnings.isEmpty());
    QVERIFY(result.profile->bridge == BridgeSettings());
}

void TestProfileBridge::defaultsAreNotWritten()
{
    Profile p;
    QVERIFY(!hatpic::serializeProfile(p).contains("bridge"));
    // The domain and the ROS version are no part of a profile: they alone write nothing.
    p.bridge.domainId = 42;
    p.bridge.rosVersion = 1;
    QVERIFY(!hatpic::serializeProfile(p).contains("bridge"));
    p.bridge.feedback.gain = 0.2;
    QVERIFY(hatpic::serializeProfile(p).contains("\"bridge\": {"));
}

void TestProfileBridge::roundTripExact()
{
    Profile p;
    p.name = u"Robot"_s;
    p.bridge = changedSettings();
    const QByteArray text = hatpic::serializeProfile(p);
    const auto result = hatpic::parseProfile(text);
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n') + u'\n' + QString::fromUtf8(text)));
    QVERIFY(result.warnings.isEmpty());
    QVERIFY2(result.profile->bridge == p.bridge, text.constData());
    QVERIFY(*result.profile == p);
    QCOMPARE(hatpic::serializeProfile(*result.profile), text);

    // Through a file, as Save profile and --profile use it.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"robot.json"_s);
    QCOMPARE(hatpic::writeProfile(p, path), QString());
    const auto read = hatpic::readProfile(path);
    QVERIFY(read.ok());
    QVERIFY(read.profile->bridge == p.bridge);

    // "auto" reads back as no axis.
    p.bridge.referenceAxis.reset();
    const auto autoAxis = hatpic::parseProfile(hatpic::serializeProfile(p));
    QVERIFY(autoAxis.ok());
    QVERIFY(!autoAxis.profile->bridge.referenceAxis.has_value());
}

void TestProfileBridge::exactText()
{
    BridgeSettings s;
    s.feedback.gain = 0.5;
    const QByteArray expected = "{\n"
                                "  \"joint_states_topic\": \"/hatpic/joint_states\",\n"
                                "  \"twist_topic\": \"/hatpic/twist\",\n"
                                "  \"twist_unstamped_topic\": \"\",\n"
                                "  \"pose_topic\": \"/hatpic/pose\",\n"
                                "  \"feedback_topic\": \"/hatpic/feedback\",\n"
                                "  \"wrench_topic\": \"/wrench_estimation\",\n"
                                "  \"wrench_unstamped_topic\": \"\",\n"
                                "  \"enable_topic\": \"\",\n"
                                "  \"joint_jog_topic\": \"\",\n"
                                "  \"imu_topic\": \"/hatpic/imu\",\n"
                                "  \"axis_topic\": \"\",\n"
                                "  \"axis_index_topic\": \"\",\n"
                                "  \"namespace\": \"\",\n"
                                "  \"rate\": 100.0,\n"
                                "  \"frame_id\": \"hatpic\",\n"
                                "  \"joint_name\": \"hatpic_knob\",\n"
                                "  \"axis\": \"auto\",\n"
                                "  \"knob_axes\": \"linear.y,linear.z,angular.z\",\n"
                                "  \"origin\": [0.0, 0.0, 0.0],\n"
                                "  \"component\": \"force.z\",\n"
                                "  \"gain\": 0.5,\n"
                                "  \"limit\": 0.154,\n"
                                "  \"stale\": 0.5,\n"
                                "  \"qos\": \"reliable\",\n"
                                "  \"depth\": 10\n"
                                "}";
    QCOMPARE(hatpic::bridgeSettingsJson(s, 0), expected);
}

void TestProfileBridge::missingKeysKeepDefaults()
{
    const auto result =
        hatpic::parseProfile(document(QJsonObject{{u"gain"_s, 0.3}, {u"limit"_s, 0.1}}));
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    BridgeSettings expected;
    expected.feedback.gain = 0.3;
    expected.feedback.limit = 0.1;
    QVERIFY(result.profile->bridge == expected);
}

void TestProfileBridge::rejects_data()
{
    QTest::addColumn<QJsonValue>("bridge");
    QTest::addColumn<QStringList>("errors");
    QTest::newRow("not an object")
        << QJsonValue(5) << QStringList{u"host.bridge: must be an object, got 5"_s};
    QTest::newRow("gain a string")
        << QJsonValue(QJsonObject{{u"gain"_s, u"0.2"_s}})
        << QStringList{u"host.bridge.gain: must be a number, got \"0.2\""_s};
    QTest::newRow("gain too large")
        << QJsonValue(QJsonObject{{u"gain"_s, 1000}})
        << QStringList{u"host.bridge: gain: must be from -100 to 100, got 1000"_s};
    QTest::newRow("limit negative") << QJsonValue(QJsonObject{{u"limit"_s, -1}})
                                    << QStringList{u"host.bridge: limit: must be from 0 to 10 "
                                                   u"N·m, got -1"_s};
    QTest::newRow("rate zero") << QJsonValue(QJsonObject{{u"rate"_s, 0}})
                               << QStringList{u"host.bridge: publish rate: must be above 0 and "
                                              u"at most 1000 Hz, got 0"_s};
    QTest::newRow("depth fractional")
        << QJsonValue(QJsonObject{{u"depth"_s, 1.5}})
        << QStringList{u"host.bridge.depth: must be a whole number, got 1.5"_s};
    QTest::newRow("depth zero") << QJsonValue(QJsonObject{{u"depth"_s, 0}})
                                << QStringList{u"host.bridge: depth: must be a whole number "
                                               u"from 1 to 1000, got 0"_s};
    QTest::newRow("origin short")
        << QJsonValue(QJsonObject{{u"origin"_s, QJsonArray{1, 2}}})
        << QStringList{u"host.bridge.origin: must be an array of three numbers [x, y, z] in "
                       u"metres, got an array"_s};
    QTest::newRow("axis unknown")
        << QJsonValue(QJsonObject{{u"axis"_s, u"up"_s}})
        << QStringList{u"host.bridge.axis: must be \"auto\" or one of \"linear.x\" … "
                       u"\"angular.z\", got \"up\""_s};
    QTest::newRow("component a number")
        << QJsonValue(QJsonObject{{u"component"_s, 2}})
        << QStringList{u"host.bridge.component: must be one of \"force.x\" … \"torque.z\", "
                       u"got 2"_s};
    QTest::newRow("qos unknown")
        << QJsonValue(QJsonObject{{u"qos"_s, u"fast"_s}})
        << QStringList{u"host.bridge.qos: must be \"reliable\" or \"best-effort\", got \"fast\""_s};
    QTest::newRow("topic invalid")
        << QJsonValue(QJsonObject{{u"twist_topic"_s, u"/9bad"_s}})
        << QStringList{u"host.bridge: twist topic: '/9bad' is not a ROS topic name (letters, "
                       u"digits and '_' between single '/', not starting with a digit)"_s};
    QTest::newRow("two at once")
        << QJsonValue(QJsonObject{{u"stale"_s, 0}, {u"frame_id"_s, false}})
        << QStringList{u"host.bridge.frame_id: must be a string, got false"_s,
                       u"host.bridge: stale after: must be above 0 and at most 10 s, got 0"_s};
}

void TestProfileBridge::rejects()
{
    QFETCH(QJsonValue, bridge);
    QFETCH(QStringList, errors);
    const auto result = hatpic::parseProfile(document(bridge));
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, errors);
}

void TestProfileBridge::unknownKeysWarn()
{
    const auto result = hatpic::parseProfile(document(
        QJsonObject{{u"colour"_s, u"red"_s}, {u"domain"_s, 3}, {u"ros"_s, 1}, {u"gain"_s, 0.1}}));
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QCOMPARE(result.warnings, (QStringList{u"unknown key \"host.bridge.colour\" ignored"_s,
                                           u"unknown key \"host.bridge.domain\" ignored"_s,
                                           u"unknown key \"host.bridge.ros\" ignored"_s}));
    QCOMPARE(result.profile->bridge.feedback.gain, 0.1);
    QCOMPARE(result.profile->bridge.domainId, 0);
    QCOMPARE(result.profile->bridge.rosVersion, 2);
}

void TestProfileBridge::writeRefusesInvalid()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"bad.json"_s);
    Profile p;
    p.bridge.feedback.limit = 50;
    const QString error = hatpic::writeProfile(p, path);
    QVERIFY2(error.contains(u"host.bridge: limit: must be from 0 to 10 N·m, got 50"_s),
             qPrintable(error));
    QVERIFY(!QFile::exists(path));
}

QTEST_GUILESS_MAIN(TestProfileBridge)

#include "tst_profilebridge.moc"
