// Profiles with effects (profile.md, effects.md § 2): the optional device.effects object, its
// defaults, errors, warnings, round trips and the effect presets.
#include "model/derived.h"
#include "model/effects.h"
#include "profile/profile.h"
#include "sim/offlinesimulation.h"
#include "sim/servoplant.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

QByteArray profileText(const QByteArray &effects)
{
    QByteArray device = R"("D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.15, "K_max": 0.4,
                           "N": 0.1, "Q_dz": 0.02, "theta0": 0.0)";
    if (!effects.isEmpty())
        device += ", \"effects\": " + effects;
    return R"({"format": "hatpic-profile", "version": 1, "device": {)" + device + "}}";
}

EffectParams someEffects()
{
    return EffectParams{.detent_strength = 0.05,
                        .detent_spacing = 0.25,
                        .detent_range = 1.0,
                        .wall_min = -0.7,
                        .wall_max = 0.6,
                        .wall_stiffness = 3,
                        .wall_damping = 0.01};
}

} // namespace

class TestProfileEffects : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void withoutEffectsLoadsDefaults();
    void partialObjectKeepsDefaults();
    void roundTrip();
    void defaultsAreNotWritten();
    void errorsNameTheField_data();
    void errorsNameTheField();
    void unknownKeyIsReported();
    void duplicateKeyIsRefused();
    void writerRefusesInvalidEffects();
    void effectPresets();
    void effectPresetsDoNotChatter_data();
    void effectPresetsDoNotChatter();
};

void TestProfileEffects::withoutEffectsLoadsDefaults()
{
    const ProfileReadResult r = parseProfile(profileText({}));
    QVERIFY2(r.ok(), qPrintable(r.errors.join(u'\n')));
    QVERIFY(r.warnings.isEmpty());
    QVERIFY(r.profile->effects == EffectParams{});
}

void TestProfileEffects::partialObjectKeepsDefaults()
{
    const ProfileReadResult r = parseProfile(profileText(R"({"wall_max": 0.5})"));
    QVERIFY2(r.ok(), qPrintable(r.errors.join(u'\n')));
    EffectParams expected;
    expected.wall_max = 0.5;
    QVERIFY(r.profile->effects == expected);
}

void TestProfileEffects::roundTrip()
{
    Profile p;
    p.name = u"fx"_s;
    p.effects = someEffects();
    const QByteArray text = serializeProfile(p);
    QVERIFY(text.contains("\"effects\": {"));
    QVERIFY(text.indexOf("\"theta0\"") < text.indexOf("\"effects\""));
    QVERIFY(text.indexOf("\"effects\"") < text.indexOf("\"host\""));
    const ProfileReadResult r = parseProfile(text);
    QVERIFY2(r.ok(), qPrintable(r.errors.join(u'\n')));
    QVERIFY(r.warnings.isEmpty());
    QVERIFY(r.profile->effects == p.effects);
    QCOMPARE(serializeProfile(*r.profile), text);
}

void TestProfileEffects::defaultsAreNotWritten()
{
    Profile p;
    QVERIFY(!serializeProfile(p).contains("effects"));
    // A device's read-back of the defaults (±π moved one float inside) travels as the
    // defaults: not written either, so a profile read from such a device stays as before.
    p.effects = roundedForWire(EffectParams{}, p.host.tau_limit);
    QVERIFY(p.effects != EffectParams{});
    QVERIFY(!serializeProfile(p).contains("effects"));
}

void TestProfileEffects::errorsNameTheField_data()
{
    QTest::addColumn<QByteArray>("effects");
    QTest::addColumn<QString>("error");
    QTest::newRow("not an object")
        << QByteArray("[1]") << u"device.effects: must be an object, got an array"_s;
    QTest::newRow("not a number") << QByteArray(R"({"wall_min": "-1"})")
                                  << u"device.effects.wall_min: must be a number, got \"-1\""_s;
    QTest::newRow("above tau_limit")
        << QByteArray(R"({"detent_strength": 0.5})")
        << u"device.effects.detent_strength: must be ≤ tau_limit (0.44), got 0.5"_s;
    QTest::newRow("wall on the wrong side")
        << QByteArray(R"({"wall_max": -0.1})") << u"device.effects.wall_max"_s;
    QTest::newRow("spacing too small")
        << QByteArray(R"({"detent_spacing": 0.001})") << u"device.effects.detent_spacing"_s;
}

void TestProfileEffects::errorsNameTheField()
{
    QFETCH(QByteArray, effects);
    QFETCH(QString, error);
    const ProfileReadResult r = parseProfile(profileText(effects));
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors.first().startsWith(error), qPrintable(r.errors.first()));
}

void TestProfileEffects::unknownKeyIsReported()
{
    const ProfileReadResult r = parseProfile(profileText(R"({"wall_colour": 1})"));
    QVERIFY(r.ok());
    QCOMPARE(r.warnings, QStringList{u"unknown key \"device.effects.wall_colour\" ignored"_s});
}

void TestProfileEffects::duplicateKeyIsRefused()
{
    const ProfileReadResult r = parseProfile(profileText(R"({"wall_max": 0.5, "wall_max": 0.6})"));
    QVERIFY(!r.ok());
    QVERIFY2(r.errors.first().contains(u"duplicate key"), qPrintable(r.errors.join(u'\n')));
}

void TestProfileEffects::writerRefusesInvalidEffects()
{
    Profile p;
    p.effects.wall_stiffness = 60; // above 50
    const QString error = writeProfile(p, u"/nonexistent-dir/x.json"_s);
    QVERIFY2(error.contains(u"device.effects.wall_stiffness"), qPrintable(error));
}

// docs/profile.md argues these numbers; the checks are the claims it makes.
void TestProfileEffects::effectPresets()
{
    const Profile detents = *preset(u"Detents"_s);
    const Profile walled = *preset(u"Walled"_s);
    constexpr double h = 1e-3; // the simulator's and the firmware's control period [s]
    const double b = ServoPlant::kViscousFriction;

    // Detents: rest positions every s out to ±0.8 rad: four on each side of center.
    const EffectParams &d = detents.effects;
    int restPositions = 0;
    for (int i = 1; i * d.detent_spacing <= 0.8 + 1e-12; ++i)
        restPositions += 2;
    QCOMPARE(restPositions, 8);
    QVERIFY(d.detent_range >= 0.8 + d.detent_spacing / 2); // the outermost well is whole
    // Each well holds the knob against the re-centering spring, out to the last.
    QVERIFY(d.detent_strength > 1.5 * detents.device.K_min * 0.8);
    const EffectFigures fd = deriveEffectFigures(d, detents.device, b, h);
    QVERIFY(!fd.detentsStifferThanNotch);
    QVERIFY(!deriveFigures(detents.device, detents.host).rings());

    // Walled: end stops at ±0.5 rad, passive with margin (K_w·h/2 at most half of b).
    const EffectParams &w = walled.effects;
    QCOMPARE(w.wall_min, -0.5);
    QCOMPARE(w.wall_max, 0.5);
    const EffectFigures fw = deriveEffectFigures(w, walled.device, b, h);
    QVERIFY(fw.wallPassivityMargin >= b / 2);
    // The gentle hand (0.06 N·m) reaches the walls over the light spring.
    QVERIFY(walled.device.K_min * 0.5 < 0.06);
}

void TestProfileEffects::effectPresetsDoNotChatter_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("hand");
    for (const QString &name : {u"Detents"_s, u"Walled"_s}) {
        // The tuner's gentle hand (SimulatorPanel::gentleHand) and a brisk one.
        QTest::newRow(qPrintable(name + u", gentle"_s)) << name << u"sine:0.06:0.2"_s;
        QTest::newRow(qPrintable(name + u", brisk"_s)) << name << u"sine:0.2:1"_s;
    }
}

// On the simulated servo (its lag, ticks and load quantisation), the knob crosses each edge
// an effect puts in its way (the midpoints between detents, the walls) only as often as the
// hand sweeps it there — at most twice per hand period. A buzz crosses the same edge again
// and again: 16 times in one second for a wall of K_w = 3 N·m/rad under the brisk hand,
// whose own frequency √(K_w/D_adm) = 173 rad/s outruns the servo's 25 Hz loop.
void TestProfileEffects::effectPresetsDoNotChatter()
{
    QFETCH(QString, name);
    QFETCH(QString, hand);
    const Profile p = *preset(name);
    OfflineSimulationConfig config;
    config.device = p.device;
    config.effects = p.effects;
    config.host = p.host;
    config.hand = *HandInput::parse(hand);
    config.duration = 8.0;
    QVERIFY(OfflineSimulation::check(config).isEmpty());
    QList<double> theta;
    OfflineSimulation sim(config);
    while (!sim.atEnd()) {
        const Sample s = sim.next();
        QVERIFY(!sim.failed());
        theta << s.theta - p.device.theta0;
    }
    QList<double> edges;
    const EffectParams &fx = p.effects;
    if (fx.detent_range > 0) {
        for (int i = -5; i < 5; ++i)
            edges << (i + 0.5) * fx.detent_spacing;
    }
    if (fx.wall_stiffness > 0)
        edges << fx.wall_min << fx.wall_max;
    constexpr double kHysteresis = 0.003; // two encoder ticks: jitter at rest is no crossing
    int worst = 0;
    for (const double edge : std::as_const(edges)) {
        QList<double> times;
        int side = 0;
        for (qsizetype k = 0; k < theta.size(); ++k) {
            const int now = theta[k] > edge + kHysteresis   ? 1
                            : theta[k] < edge - kHysteresis ? -1
                                                            : 0;
            if (now != 0 && side != 0 && now != side)
                times << double(k) / config.rateHz;
            if (now != 0)
                side = now;
        }
        for (qsizetype i = 0, j = 0; i < times.size(); ++i) {
            while (j < times.size() && times[j] - times[i] < 1.0)
                ++j;
            worst = std::max(worst, int(j - i));
        }
    }
    double reach = 0;
    for (const double e : std::as_const(theta))
        reach = std::max(reach, std::abs(e));
    qInfo("%s under %s: |e| up to %.3f rad, at most %d crossings of one edge in 1 s",
          qPrintable(name), qPrintable(hand), reach, worst);
    QVERIFY2(worst <= 4, qPrintable(QString::number(worst)));
    if (hand == u"sine:0.06:0.2") {
        if (name == u"Walled")
            QVERIFY(reach > 0.5 && reach < 0.55); // reaches a wall and is held near it
        else
            QVERIFY(reach > 0.75 && reach < 0.9); // clicks out to the last detent, no further
    }
}

QTEST_GUILESS_MAIN(TestProfileEffects)
#include "tst_profileeffects.moc"
