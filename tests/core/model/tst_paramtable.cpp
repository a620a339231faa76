// The parameter table (model/paramtable.h) is the one home of each parameter's facts: the
// validation rules follow it, wire rounding stays inside its ranges, and docs/model.md's
// parameter table says the same thing, row for row.
#include "model/paramtable.h"

#include <QFile>
#include <QRegularExpression>
#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

QString text(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

//! The cells of docs/model.md's "index | field | … | default" table, one list per row.
QList<QStringList> docsTableRows()
{
    QFile file(qEnvironmentVariable("HATPIC_SOURCE_DIR") + u"/docs/model.md"_s);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<QStringList> rows;
    bool inTable = false;
    for (const QString &line : QString::fromUtf8(file.readAll()).split(u'\n')) {
        if (line.startsWith(u"| index | field"))
            inTable = true;
        else if (inTable && !line.startsWith(u'|'))
            break;
        else if (inTable && !line.startsWith(u"|--")) {
            QStringList cells = line.split(u'|');
            for (QString &c : cells)
                c = c.trimmed();
            rows.append(cells.mid(1, cells.size() - 2));
        }
    }
    return rows;
}

} // namespace

class TestParamTable : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void wireOrderAndNames()
    {
        QCOMPARE(int(kDeviceFields.size()), DeviceParams::kFieldCount);
        DeviceParams p;
        for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
            p.setField(i, 100.0 + i);
            QCOMPARE(deviceFieldIndex(kDeviceFields[std::size_t(i)].name), i);
        }
        // setField follows the table's member for each wire index, in ParamBlock order.
        QCOMPARE(p.D_adm, 100.0);
        QCOMPARE(p.M_adm, 101.0);
        QCOMPARE(p.K_min, 102.0);
        QCOMPARE(p.K_max, 103.0);
        QCOMPARE(p.N, 104.0);
        QCOMPARE(p.Q_dz, 105.0);
        QCOMPARE(p.theta0, 106.0);
    }

    void boundsAreTheValidationRules()
    {
        // Every present bound is exactly where validation starts or stops refusing.
        for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
            const DeviceFieldSpec &s = kDeviceFields[std::size_t(i)];
            const auto refusedAt = [i](double v) {
                DeviceParams p;
                p.K_max = 50; // room for K_min's cross rule
                p.N = std::numbers::pi / 2;
                p.Q_dz = 0;
                p.setField(i, v);
                for (const Violation &x : validate(p)) {
                    if (x.index == i)
                        return true;
                }
                return false;
            };
            if (s.lower.present) {
                QCOMPARE(refusedAt(s.lower.value), !s.lower.inclusive);
                QVERIFY(refusedAt(std::nextafter(s.lower.value, -1e300)));
            }
            if (s.upper.present) {
                QCOMPARE(refusedAt(s.upper.value), !s.upper.inclusive);
                QVERIFY(refusedAt(std::nextafter(s.upper.value, 1e300)));
            }
        }
    }

    void rangeTexts()
    {
        QCOMPARE(text(rangeText(kDeviceFields[0])), u"1e-06 ≤ D_adm ≤ 1"_s);
        QCOMPARE(text(rangeText(kDeviceFields[2])), u"0 ≤ K_min ≤ K_max"_s);
        QCOMPARE(text(rangeText(kDeviceFields[4])), u"0 < N ≤ π/2"_s);
        QCOMPARE(text(rangeText(kDeviceFields[5])), u"0 ≤ Q_dz < N"_s);
        QCOMPARE(text(rangeText(kDeviceFields[6])), u"−π ≤ θ0 ≤ π"_s);
        QCOMPARE(text(rangeText(kHostFields[1])), u"0 < tau_limit ≤ 10"_s);
    }

    void docsAgree()
    {
        const QList<QStringList> rows = docsTableRows();
        QCOMPARE(rows.size(), DeviceParams::kFieldCount);
        const DeviceParams defaults;
        for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
            const DeviceFieldSpec &s = kDeviceFields[std::size_t(i)];
            const QStringList &row = rows.at(i);
            QCOMPARE(row.size(), 6);
            QCOMPARE(row.at(0).toInt(), i);
            QCOMPARE(row.at(1), text(s.name));
            QCOMPARE(row.at(3), text(s.unit));
            QCOMPARE(row.at(4), text(rangeText(s)));
            bool ok = false;
            QCOMPARE(row.at(5).toDouble(&ok), defaults.field(i));
            QVERIFY(ok);
        }
    }

    // A field's tuning range lies within its valid range and holds its default, so a slider
    // neither offers refused values nor starts off its end; a step is a fraction of it.
    void tuningRangesAreValid()
    {
        const auto check = [](const auto &table, const auto &defaults) {
            for (const auto &f : table) {
                const FieldDisplay &d = f.display;
                const double upper = f.upper.external ? kHostFields[1].upper.value
                                     : f.upper.present
                                         ? f.upper.value
                                         : table[std::size_t(f.cross.field)].upper.value;
                QVERIFY2(d.low >= f.lower.value && d.high <= upper && d.low < d.high,
                         f.name.data());
                QVERIFY2(d.step > 0 && d.step < d.high - d.low, f.name.data());
                const double value = defaults.*f.member;
                QVERIFY2(value >= d.low && value <= d.high, f.name.data());
            }
        };
        check(kDeviceFields, DeviceParams{});
        check(kHostFields, HostParams{});
        check(kEffectFields, EffectParams{});
    }
};

QTEST_GUILESS_MAIN(TestParamTable)
#include "tst_paramtable.moc"
