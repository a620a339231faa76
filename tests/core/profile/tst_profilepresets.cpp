// Tests for the built-in presets (profile.md § Built-in presets): compiled in, each file valid
// and exactly what the writer makes of it, "Default" the spec's defaults, each feeling as it is
// named (the figures profile.md quotes), looked up by name whatever its case.

#include "model/derived.h"
#include "profile/profile.h"
#include "readback.h"

#include <QFile>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::Profile;
using hatpic::test::identical;
using hatpic::test::readAll;

} // namespace

class TestProfilePresets : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void presetResourcesLinked();
    void presetsLoadAndValidate();
    void presetsFeelAsNamed();
    void presetLookup();
};

// Runs first: the ":/presets" resources must be present in a test executable before any
// profile code runs, which shows CMake linked the static library's resource object.
void TestProfilePresets::presetResourcesLinked()
{
    QVERIFY(QFile::exists(u":/presets/default.json"_s));
    QVERIFY(QFile::exists(u":/presets/soft.json"_s));
    QVERIFY(QFile::exists(u":/presets/notchy.json"_s));
    const std::optional<Profile> soft = hatpic::preset(u"Soft"_s);
    QVERIFY(soft.has_value());
    QCOMPARE(soft->name, u"Soft"_s);
}

void TestProfilePresets::presetsLoadAndValidate()
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
        QCOMPARE(readAll(path), hatpic::serializeProfile(*result.profile));
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
void TestProfilePresets::presetsFeelAsNamed()
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

void TestProfilePresets::presetLookup()
{
    QVERIFY(hatpic::preset(u"soft"_s).has_value());
    QCOMPARE(hatpic::preset(u"NOTCHY"_s)->name, u"Notchy"_s);
    QVERIFY(!hatpic::preset(u"Hard"_s).has_value());
    QVERIFY(!hatpic::preset(QString()).has_value());
}

QTEST_GUILESS_MAIN(TestProfilePresets)
#include "tst_profilepresets.moc"
