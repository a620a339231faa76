// What the tests of hatpicctl's core commands share (tst_hatpicctl, tst_hatpicctlsimulate,
// tst_hatpicctldevice): a base test class that writes the profile files they hand to hatpicctl
// into a folder of its own, the sample CSV's header and form, and the stiffness zones' names.
#pragma once

#include "ctlprocess.h"
#include "model/params.h"
#include "profile/profile.h"
#include "telemetry/numbertext.h"
#include "telemetry/samplecolumns.h"

#include <QByteArray>
#include <QFile>
#include <QList>
#include <QObject>
#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace hatpic::test {

//! The base of the hatpicctl test classes: its initTestCase() writes the profile files.
class CtlTest : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        Profile profile;
        profile.name = u"Default"_s;
        m_default = writeProfileFile(u"default.json"_s, profile);
        QVERIFY(!m_default.isEmpty());

        profile.name = u"Exact"_s;
        profile.device = exactParams();
        m_exact = writeProfileFile(u"exact.json"_s, profile);
        QVERIFY(!m_exact.isEmpty());

        profile.device.theta0 = -0.5;
        profile.device.Q_dz = 0.0625;
        profile.host.mode = ReferenceMode::Rotation;
        profile.host.v_max = 2.0;
        profile.host.ref_deadzone = false;
        m_shifted = writeProfileFile(u"shifted.json"_s, profile);
        QVERIFY(!m_shifted.isEmpty());

        m_invalid = writeFile(u"invalid.json"_s, R"({
  "format": "hatpic-profile", "version": 1,
  "device": {"D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.9, "K_max": 0.4,
             "N": 0.1, "Q_dz": 0.2, "theta0": 0.0}
})");
        QVERIFY(!m_invalid.isEmpty());

        profile = Profile{};
        profile.device.N = 0.1;
        profile.device.Q_dz = std::nextafter(0.1, 0.0);
        QCOMPARE(float(profile.device.Q_dz), float(profile.device.N)); // the premise of the case
        m_float = writeProfileFile(u"float.json"_s, profile);
        QVERIFY(!m_float.isEmpty());
    }

protected:
    QString writeFile(const QString &name, const QByteArray &content)
    {
        const QString path = m_dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return {};
        file.write(content);
        return path;
    }

    QString writeProfileFile(const QString &name, const Profile &profile)
    {
        const QString path = m_dir.filePath(name);
        const QString error = writeProfile(profile, path);
        return error.isEmpty() ? path : QString();
    }

    QTemporaryDir m_dir;
    QString m_default; //!< the default parameters
    QString m_exact;   //!< exactParams(), host defaults
    QString m_shifted; //!< exactParams() with the dead zone and θ0 elsewhere
    QString m_invalid; //!< K_min > K_max and Q_dz > N
    QString m_float;   //!< valid in double, Q_dz = N once rounded to float32
};

inline QString stiffnessName(double theta, const DeviceParams &p)
{
    const double a = std::abs(theta - p.theta0);
    return a < p.Q_dz ? u"dead zone"_s : a <= p.N ? u"notch"_s : u"outer"_s;
}

inline const QByteArray kSampleHeader =
    "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,tau_pc,pc_reserve";

//! Why `csv` is not the sample CSV of the column table (its header, one field per column, every
//! number in the one number format); empty when it is. `floatDigits` counts the values written
//! with a float's digits (they read back as a double that is not a float).
inline QString sampleCsvFormProblem(const QByteArray &csv, int &floatDigits)
{
    floatDigits = 0;
    const QList<QByteArray> lines = csv.split('\n');
    if (lines.first() != sampleCsvHeader())
        return u"header: "_s + QString::fromUtf8(lines.first());
    for (qsizetype i = 1; i + 1 < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        if (fields.size() != qsizetype(kSampleColumns.size()))
            return u"fields: "_s + QString::fromUtf8(lines[i]);
        for (qsizetype k = 0; k + 1 < fields.size(); ++k) {
            const double value = fields[k].toDouble();
            if (!fields[k].isEmpty() && QString::fromLatin1(fields[k]) != compactNumberText(value))
                return u"number format: "_s + QString::fromUtf8(fields[k]);
            const double asFloat = static_cast<float>(value);
            floatDigits += k > 0 && asFloat != value ? 1 : 0;
        }
    }
    return {};
}

} // namespace hatpic::test
