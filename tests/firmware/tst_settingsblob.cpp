// The ESP32's NVS record of SAVE_PARAMS (firmware/src/settingsblob.*): round trip of both
// blocks (and the passivity block), versions 1 and 2 still read, and every damaged or foreign blob
// refused.
#include "settingsblob.h"

#include "protocol/crc16.h"

#include <QTest>

using namespace hatpic;
using namespace hatpic::esp32;

namespace {

fw::StoredSettings sample()
{
    fw::StoredSettings s;
    s.params.K_max = 0.5f;
    s.params.theta0 = -0.25f;
    s.effects.detent_strength = 0.05f;
    s.effects.detent_range = 0.8f;
    s.effects.wall_min = -0.5f;
    s.effects.wall_max = 0.5f;
    s.effects.wall_stiffness = 5.0f;
    s.params.D_adm = double(1e-4f);
    s.params.M_adm = double(1e-2f);
    s.params.K_min = double(0.15f);
    s.params.N = double(0.1f);
    s.params.Q_dz = double(0.02f);
    s.effects.detent_spacing = double(0.2f);
    s.passivity.pc_damping_max = 0.25;
    s.passivity.pc_reserve_max = double(0.015f);
    return s;
}

} // namespace

class TestSettingsBlob : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip()
    {
        const fw::StoredSettings in = sample();
        const SettingsBlob blob = encodeSettingsBlob(in);
        fw::StoredSettings out;
        QVERIFY(decodeSettingsBlob(blob, out));
        QCOMPARE(out, in);
    }

    void versionOneHasDefaultEffects()
    {
        // A blob written before effects: version 1, parameters only.
        const fw::StoredSettings in = sample();
        const SettingsBlob v2blob = encodeSettingsBlob(in);
        std::vector<std::uint8_t> v1(v2blob.begin(), v2blob.begin() + 4 + 28);
        v1[0] = 1;
        v1[2] = 28;
        const std::uint16_t crc = v2::crc16(v1);
        v1.push_back(std::uint8_t(crc));
        v1.push_back(std::uint8_t(crc >> 8));
        fw::StoredSettings out;
        QVERIFY(decodeSettingsBlob(v1, out));
        QCOMPARE(out.params, in.params);
        QCOMPARE(out.effects, EffectParams{});
    }

    void versionTwoHasDefaultPassivity()
    {
        // A blob written before the passivity controller: version 2, no passivity block.
        const fw::StoredSettings in = sample();
        const SettingsBlob v3blob = encodeSettingsBlob(in);
        std::vector<std::uint8_t> old(v3blob.begin(), v3blob.begin() + 4 + 56);
        old[0] = 2;
        old[2] = 56;
        const std::uint16_t crc = v2::crc16(old);
        old.push_back(std::uint8_t(crc));
        old.push_back(std::uint8_t(crc >> 8));
        fw::StoredSettings out;
        QVERIFY(decodeSettingsBlob(old, out));
        QCOMPARE(out.params, in.params);
        QCOMPARE(out.effects, in.effects);
        QCOMPARE(out.passivity, PassivityParams{});
    }

    void damagedBlobsAreRefused()
    {
        const SettingsBlob good = encodeSettingsBlob(sample());
        fw::StoredSettings out;
        out.params.K_max = 42;
        for (std::size_t i = 0; i < good.size(); ++i) {
            SettingsBlob bad = good;
            bad[i] ^= 0x10;
            QVERIFY2(!decodeSettingsBlob(bad, out), qPrintable(QString::number(i)));
        }
        QVERIFY(!decodeSettingsBlob(std::span(good).first(good.size() - 1), out));
        QVERIFY(!decodeSettingsBlob({}, out));
        QCOMPARE(out.params.K_max, 42.0); // untouched
    }
};

QTEST_GUILESS_MAIN(TestSettingsBlob)
#include "tst_settingsblob.moc"
