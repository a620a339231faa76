// hatpicctl run as a real process, and the model computed again independently: the parts the
// hatpicctl tests share (tst_hatpicctl, tst_hatpicctlsimulate, tst_hatpicctldevice,
// tst_hatpicctleffects and others).
#pragma once

#include "model/params.h"
#include "processrun.h"

#include <QByteArray>
#include <QList>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTest>

#include <algorithm>
#include <cmath>

namespace hatpic::test {

using namespace Qt::StringLiterals;

constexpr int kProcessTimeoutMs = 60000;

inline Run runCtl(const QStringList &arguments, int timeoutMs = kProcessTimeoutMs,
                  const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPICCTL_PATH));
    process.setArguments(arguments);
    process.setProcessEnvironment(environment);
    return runToEnd(process, timeoutMs);
}

//! runCtl() while this thread's event loop runs: devices the test scripts on pseudo-terminals
//! (ScriptedDevice) keep answering.
inline Run runCtlServing(const QStringList &arguments, int timeoutMs = kProcessTimeoutMs)
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPICCTL_PATH));
    process.setArguments(arguments);
    return runToEnd(process, timeoutMs, true);
}

inline QString describe(const Run &run)
{
    return u"exit "_s + QString::number(run.code) + u"\nstderr: "_s + QString::fromUtf8(run.err) +
           u"\nstdout (first 400 bytes): "_s + QString::fromUtf8(run.out.left(400));
}

// A failure must be told in one sentence: exactly one non-empty line on stderr.
inline bool isOneLine(const QByteArray &err)
{
    const QByteArray trimmed = err.trimmed();
    return !trimmed.isEmpty() && !trimmed.contains('\n');
}

inline QList<QList<double>> parseCsv(const QByteArray &text, const QByteArray &expectedHeader,
                                     QString *problem)
{
    QList<QByteArray> lines = text.split('\n');
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    if (lines.isEmpty() || lines.first() != expectedHeader) {
        *problem = u"header is \""_s + QString::fromUtf8(lines.value(0)) + u'"';
        return {};
    }
    const qsizetype columns = expectedHeader.count(',') + 1;
    QList<QList<double>> rows;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> cells = lines[i].split(',');
        if (cells.size() != columns) {
            *problem = u"line "_s + QString::number(i + 1) + u" has "_s +
                       QString::number(cells.size()) + u" cells"_s;
            return {};
        }
        QList<double> row;
        for (const QByteArray &cell : cells) {
            bool ok = false;
            row << cell.toDouble(&ok);
            if (!ok) {
                *problem = u"line "_s + QString::number(i + 1) + u": not a number: "_s +
                           QString::fromUtf8(cell);
                return {};
            }
        }
        rows << row;
    }
    return rows;
}

// |actual − expected| within `tolerance`, relative above 1 and absolute below.
inline bool closeTo(double actual, double expected, double tolerance)
{
    return std::abs(actual - expected) <= tolerance * std::max(1.0, std::abs(expected));
}

// K_rec of model.md § 2, written out again here so that the test does not trust the library.
inline double expectedStiffness(const DeviceParams &p, double theta)
{
    const double a = std::abs(theta - p.theta0);
    if (a < p.Q_dz)
        return 0.0;
    if (a <= p.N)
        return p.K_max;
    const double kT = p.K_min + (p.K_max - p.K_min) * (1.0 - (a - p.N) / p.N);
    return std::clamp(kT, p.K_min, p.K_max);
}

// Parameters every one of which is exactly a 32-bit float, so the device's rounding does not
// enter the comparison with the model.
inline DeviceParams exactParams()
{
    DeviceParams p;
    p.D_adm = 0.0001220703125; // 2^-13
    p.M_adm = 0.0078125;       // 2^-7
    p.K_min = 0.125;
    p.K_max = 0.375;
    p.N = 0.125;
    p.Q_dz = 0.015625;
    p.theta0 = 0.0625;
    return p;
}

} // namespace hatpic::test
