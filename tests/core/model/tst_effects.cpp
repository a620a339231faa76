// Haptic effects (effects.md § 1–2, § 4): the torques against hand-computed values at every
// boundary the spec names, the block's and VIBRATE's validation, the derived figures.
#include "model/effects.h"
#include "model/paramtable.h"
#include "model/servo.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr double kPi = std::numbers::pi;

EffectParams detents(double a, double s, double r)
{
    EffectParams p;
    p.detent_strength = a;
    p.detent_spacing = s;
    p.detent_range = r;
    return p;
}

EffectParams walls(double lo, double hi, double k, double b)
{
    EffectParams p;
    p.wall_min = lo;
    p.wall_max = hi;
    p.wall_stiffness = k;
    p.wall_damping = b;
    return p;
}

QStringList messages(const std::vector<Violation> &violations)
{
    QStringList out;
    for (const Violation &v : violations)
        out << QString::fromStdString(v.message());
    return out;
}

} // namespace

class TestEffects : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void defaultsRenderNothing()
    {
        const EffectParams p;
        for (double e : {-3.0, -0.5, 0.0, 0.1, 0.5, 3.0}) {
            for (double w : {-2.0, 0.0, 2.0}) {
                QCOMPARE(hatpic::detentTorque(p, e), 0.0);
                QCOMPARE(hatpic::wallTorque(p, e, w), 0.0);
            }
        }
        QVERIFY(validate(p, 0.44).empty());
    }

    void detentTorque_data()
    {
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("expected");
        const double a = 0.05, s = 0.2;
        QTest::newRow("rest position e = 0") << 0.0 << 0.0;
        QTest::newRow("quarter spacing pulls back") << s / 4 << -a;
        QTest::newRow("minus quarter spacing pulls forward") << -s / 4 << a;
        QTest::newRow("half spacing: unstable balance") << s / 2 << -a * std::sin(kPi);
        QTest::newRow("e = R exactly still applies") << 0.55 << -a * std::sin(2 * kPi * 0.55 / s);
        QTest::newRow("e = -R exactly still applies")
            << -0.55 << -a * std::sin(2 * kPi * -0.55 / s);
        QTest::newRow("just beyond R: off") << std::nextafter(0.55, 1.0) << 0.0;
        QTest::newRow("far beyond R: off") << 2.0 << 0.0;
    }
    void detentTorque()
    {
        QFETCH(double, e);
        QFETCH(double, expected);
        QCOMPARE(hatpic::detentTorque(detents(0.05, 0.2, 0.55), e), expected);
    }

    void detentsOff()
    {
        QCOMPARE(hatpic::detentTorque(detents(0.0, 0.2, 1.0), 0.05), 0.0);  // A = 0
        QCOMPARE(hatpic::detentTorque(detents(0.05, 0.2, 0.0), 0.05), 0.0); // R = 0
    }

    void wallTorque_data()
    {
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("omega");
        QTest::addColumn<double>("expected");
        const double k = 2.0, b = 0.1;
        QTest::newRow("inside: nothing") << 0.3 << 5.0 << 0.0;
        QTest::newRow("at wall_max exactly: nothing") << 0.5 << 5.0 << 0.0;
        QTest::newRow("at wall_min exactly: nothing") << -0.4 << -5.0 << 0.0;
        QTest::newRow("beyond max moving in: spring and damper") << 0.6 << 2.0 << -k * 0.1 - b * 2;
        QTest::newRow("beyond max moving out: spring only") << 0.6 << -2.0 << -k * 0.1;
        QTest::newRow("beyond max at rest: spring only") << 0.6 << 0.0 << -k * 0.1;
        QTest::newRow("beyond min moving in: spring and damper") << -0.5 << -3.0 << k * 0.1 + b * 3;
        QTest::newRow("beyond min moving out: spring only") << -0.5 << 3.0 << k * 0.1;
    }
    void wallTorque()
    {
        QFETCH(double, e);
        QFETCH(double, omega);
        QFETCH(double, expected);
        QVERIFY(std::abs(hatpic::wallTorque(walls(-0.4, 0.5, 2.0, 0.1), e, omega) - expected) <
                1e-12);
    }

    void wallsWithoutStiffnessOrDamping()
    {
        QCOMPARE(hatpic::wallTorque(walls(-0.4, 0.5, 0.0, 0.0), 0.9, 1.0), 0.0);
        // A damper alone still brakes a knob moving further in.
        QCOMPARE(hatpic::wallTorque(walls(-0.4, 0.5, 0.0, 0.2), 0.9, 1.0), -0.2);
    }

    void vibration()
    {
        const double a = 0.1, f = 50, d = 0.2;
        QCOMPARE(vibrationTorque(a, f, d, -1e-9), 0.0);
        QCOMPARE(vibrationTorque(a, f, d, 0.0), 0.0);
        QVERIFY(std::abs(vibrationTorque(a, f, d, 1.0 / (4 * f)) - a) < 1e-12);
        QVERIFY(std::abs(vibrationTorque(a, f, d, 3.0 / (4 * f)) + a) < 1e-12);
        QCOMPARE(vibrationTorque(a, f, d, d), 0.0); // t_start + d is already over
        QCOMPARE(vibrationTorque(0.0, f, d, 0.001), 0.0);
        // The float build evaluates the same function.
        QVERIFY(std::abs(vibrationTorque(0.1f, 50.0f, 0.2f, 0.005f) - 0.1f) < 1e-6f);
    }

    void validation_data()
    {
        QTest::addColumn<int>("field");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("message");
        QTest::newRow("detent_strength negative")
            << 0 << -0.01 << u"detent_strength: must be ≥ 0, got -0.01"_s;
        QTest::newRow("detent_strength above tau_limit")
            << 0 << 0.5 << u"detent_strength: must be ≤ tau_limit (0.44), got 0.5"_s;
        QTest::newRow("detent_spacing too small")
            << 1 << 0.009 << u"detent_spacing: must be ≥ 0.01, got 0.009"_s;
        QTest::newRow("detent_spacing above pi")
            << 1 << 3.2 << u"detent_spacing: must be ≤ π (3.141592653589793), got 3.2"_s;
        QTest::newRow("detent_range negative")
            << 2 << -0.1 << u"detent_range: must be ≥ 0, got -0.1"_s;
        QTest::newRow("wall_min above 0") << 3 << 0.1 << u"wall_min: must be ≤ 0, got 0.1"_s;
        QTest::newRow("wall_min below -pi")
            << 3 << -3.2 << u"wall_min: must be ≥ −π (-3.141592653589793), got -3.2"_s;
        QTest::newRow("wall_max below 0") << 4 << -0.1 << u"wall_max: must be ≥ 0, got -0.1"_s;
        QTest::newRow("wall_stiffness above 50")
            << 5 << 51.0 << u"wall_stiffness: must be ≤ 50, got 51"_s;
        QTest::newRow("wall_damping above 1")
            << 6 << 1.5 << u"wall_damping: must be ≤ 1, got 1.5"_s;
        QTest::newRow("NaN") << 6 << std::nan("") << u"wall_damping: must be finite, got nan"_s;
    }
    void validation()
    {
        QFETCH(int, field);
        QFETCH(double, value);
        QFETCH(QString, message);
        EffectParams p;
        p.setField(field, value);
        QCOMPARE(messages(validate(p, 0.44)), QStringList{message});
        QCOMPARE(firstViolatingField(p, 0.44), field);
    }

    void boundsInclusive()
    {
        EffectParams p;
        p.detent_strength = 0.44;
        p.detent_spacing = 0.01;
        p.detent_range = kPi;
        p.wall_min = 0.0;
        p.wall_max = 0.0;
        p.wall_stiffness = 50;
        p.wall_damping = 1;
        QVERIFY(validate(p, 0.44).empty());
        QCOMPARE(firstViolatingField(p, 0.44), -1);
        QCOMPARE(firstViolatingField(p, 0.4), 0); // tau_limit is the device's
    }

    // The device reports tau_limit as a float: 0.44f = 0.4399999976158142 < 0.44. The one rule
    // compares as that float, so 0.44 (the same float) is within it, and the message quotes
    // the limit as 0.44 and the value as written (issue 21).
    void torqueLimitIsTheDevicesFloat()
    {
        const double device = double(0.44f);
        QVERIFY(device < 0.44);
        EffectParams p;
        p.detent_strength = 0.44;
        QVERIFY(validate(p, device).empty());
        QCOMPARE(firstViolatingField(p, device), -1);
        QVERIFY(validate(Vibration{0.44, 100, 1}, device, 1000).empty());
        QCOMPARE(firstViolatingField(Vibration{0.44, 100, 1}, device, 1000), -1);
        // What travels is within it too: the device's own check passes.
        QCOMPARE(firstViolatingField(roundedForWire(p, device), device), -1);
        p.detent_strength = 0.45;
        QCOMPARE(messages(validate(p, device)),
                 QStringList{u"detent_strength: must be ≤ tau_limit (0.44), got 0.45"_s});
        p.detent_strength = double(std::nextafter(0.44f, 1.0f)); // the next float: beyond
        QCOMPARE(firstViolatingField(p, device), 0);
        QVERIFY(!atMostAsDeviceFloat(std::nan(""), 1));
        QVERIFY(atMostAsDeviceFloat(-1e300, 0));
        QVERIFY(!atMostAsDeviceFloat(1e300, 3e38));
    }

    void vibrationValidation()
    {
        QVERIFY(validate(Vibration{0.44, 500, 10}, 0.44, 2000).empty());
        // 1…500 Hz *and* below half the control rate: at 1 kHz, 500 Hz is refused.
        QCOMPARE(messages(validate(Vibration{0.44, 500, 10}, 0.44, 1000)),
                 QStringList{u"frequency: must be < half the control rate (500), got 500"_s});
        QVERIFY(validate(Vibration{0, 1, 0}, 0.44, 1000).empty());
        QCOMPARE(messages(validate(Vibration{0.5, 0.5, 11}, 0.44, 1000)),
                 (QStringList{u"amplitude: must be ≤ tau_limit (0.44), got 0.5"_s,
                              u"frequency: must be ≥ 1, got 0.5"_s,
                              u"duration: must be ≤ 10, got 11"_s}));
        // Below half the control rate: 300 Hz is refused at 500 Hz.
        QCOMPARE(messages(validate(Vibration{0.1, 300, 1}, 0.44, 500)),
                 QStringList{u"frequency: must be < half the control rate (250), got 300"_s});
        QCOMPARE(firstViolatingField(Vibration{0.1, 300, 1}, 0.44, 500), 1);
        QCOMPARE(firstViolatingField(Vibration{0.1, 30, 1}, 0.44, 500), -1);
    }

    void derivedFigures()
    {
        EffectParams p = detents(0.05, 0.2, 0.8);
        p.wall_stiffness = 5;
        DeviceParams d;
        const EffectFigures f = deriveEffectFigures(p, d, 0.0049, 1e-3);
        QVERIFY(std::abs(f.detentPeakStiffness - 0.05 * 2 * kPi / 0.2) < 1e-12);
        QVERIFY(std::abs(f.wallPassivityMargin - (0.0049 - 5 * 1e-3 / 2)) < 1e-15);
        QVERIFY(f.detentsStifferThanNotch); // 1.57 N·m/rad > K_max 0.4
        // b − 1.5708·0.001/2 = 0.0049 − 0.000785398
        QVERIFY(std::abs(f.detentPassivityMargin - (0.0049 - 0.05 * kPi / 0.2 * 1e-3)) < 1e-15);
        // 0.0049 < 20·π·0.001/2: detents of 2 N·m every 0.2 rad (62.8 N·m/rad) are not passive.
        QVERIFY(deriveEffectFigures(detents(2, 0.2, 0.8), d, 0.0049, 1e-3).detentPassivityMargin <
                0);
        p.detent_range = 0;
        QVERIFY(!deriveEffectFigures(p, d, 0.0049, 1e-3).detentsStifferThanNotch);
    }

    void servoLimit()
    {
        DeviceParams d;
        d.D_adm = 1e-4;
        // 1e-4·(2π·25)² = 1e-4·24674.011 = 2.4674011 N·m/rad (docs/effects.md's "near 2.5").
        QVERIFY(std::abs(servoStiffnessLimit(d, 25) - 2.4674011002723395) < 1e-12);
        d.D_adm = 4e-4;
        QVERIFY(std::abs(servoStiffnessLimit(d, 25) - 4 * 2.4674011002723395) < 1e-12);
        QCOMPARE(servoStiffnessLimit(d, 0), 0.0);
    }

    //! The rules a tuning UI warns about, each alone and only for effects that are on.
    void warnings()
    {
        using W = EffectWarning;
        using List = std::vector<W>;
        DeviceParams d; // D_adm 1e-4: the servo follows up to 2.47 N·m/rad
        const auto warned = [&](const EffectParams &p) {
            return deriveEffectFigures(p, d, 0.0049, 1e-3).warnings;
        };
        QVERIFY(warned(EffectParams{}).empty()); // the defaults render nothing
        // A soft wall inside ±π: passive (K_w·h/2 = 0.001 < b) and within the servo's reach.
        QVERIFY(warned(walls(-1, 1, 2, 0)).empty());
        // 3 N·m/rad: still passive (0.0015 < 0.0049) but above 2.47.
        QCOMPARE(warned(walls(-1, 1, 3, 0)), List{W::WallAboveServo});
        // 10 N·m/rad: 0.005 > 0.0049 as well.
        QCOMPARE(warned(walls(-1, 1, 10, 0)), (List{W::WallNotPassive, W::WallAboveServo}));
        // The same stiffness with both bounds at ±π is no wall.
        QVERIFY(warned(walls(-kPi, kPi, 10, 0)).empty());
        // Detents of 0.01 N·m every 0.2 rad: 0.314 N·m/rad, below K_max 0.4 and everything.
        QVERIFY(warned(detents(0.01, 0.2, 0.8)).empty());
        // 0.05 N·m: 1.57 N·m/rad, stiffer than the notch only.
        QCOMPARE(warned(detents(0.05, 0.2, 0.8)), List{W::DetentsStifferThanNotch});
        // 0.1 N·m: 3.14 N·m/rad, above the servo too.
        QCOMPARE(warned(detents(0.1, 0.2, 0.8)),
                 (List{W::DetentsAboveServo, W::DetentsStifferThanNotch}));
        // 2 N·m: 62.8 N·m/rad, not passive either.
        QCOMPARE(warned(detents(2, 0.2, 0.8)),
                 (List{W::DetentsNotPassive, W::DetentsAboveServo, W::DetentsStifferThanNotch}));
        // Without a range the detents are off: no warning, whatever their strength.
        QVERIFY(warned(detents(2, 0.2, 0)).empty());
        // A heavier knob moves the servo's limit: D_adm 4e-4 follows 9.87 N·m/rad.
        d.D_adm = 4e-4;
        QVERIFY(warned(walls(-1, 1, 3, 0)).empty());
        QCOMPARE(deriveEffectFigures(EffectParams{}, d, 0.0049, 1e-3).servoLimit,
                 servoStiffnessLimit(d, servo::kPositionLoopHz));
    }

    void tableNames()
    {
        for (int i = 0; i < EffectParams::kFieldCount; ++i)
            QCOMPARE(effectFieldIndex(effectFieldName(i)), i);
        QCOMPARE(effectFieldIndex("nope"), -1);
        QCOMPARE(QString::fromStdString(rangeText(kEffectFields[0])), u"0 ≤ A_det ≤ tau_limit"_s);
    }
};

QTEST_GUILESS_MAIN(TestEffects)
#include "tst_effects.moc"
