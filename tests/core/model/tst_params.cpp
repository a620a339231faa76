// Tests for the parameter types and validation rules (model.md § 1).

#include "model/params.h"

#include <QTest>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::DeviceParams;
using hatpic::HostParams;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

QStringList messages(const std::vector<hatpic::Violation> &violations)
{
    QStringList out;
    for (const auto &v : violations)
        out.append(QString::fromStdString(v.message()));
    return out;
}

DeviceParams withField(int index, double value)
{
    DeviceParams p;
    p.setField(index, value);
    return p;
}

} // namespace

Q_DECLARE_METATYPE(hatpic::DeviceParams)

class TestParams : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void defaultsMatchSpec();
    void defaultsValid();
    void fieldAccessByIndex();
    void fieldNames();
    void deviceRules_data();
    void deviceRules();
    void deviceBoundariesAccepted_data();
    void deviceBoundariesAccepted();
    void nonFinite_data();
    void nonFinite();
    void multipleViolationsAllReported();
    void firstViolatingFieldInTableOrder_data();
    void firstViolatingFieldInTableOrder();
    void hostRules_data();
    void hostRules();
    void violationCarriesFieldIndexRuleValue();
    void formatNumberShortestExact_data();
    void formatNumberShortestExact();
    void roundedForWireKeepsBounds_data();
    void roundedForWireKeepsBounds();
    void roundedForWireKeepsInvalidInvalid();
    void shortestFloatDecimal_data();
    void shortestFloatDecimal();
};

void TestParams::defaultsMatchSpec()
{
    const DeviceParams d;
    QCOMPARE(d.D_adm, 1.0e-4);
    QCOMPARE(d.M_adm, 1.0e-2);
    QCOMPARE(d.K_min, 0.15);
    QCOMPARE(d.K_max, 0.40);
    QCOMPARE(d.N, 0.10);
    QCOMPARE(d.Q_dz, 0.02);
    QCOMPARE(d.theta0, 0.0);
    const HostParams h;
    QCOMPARE(h.v_max, 1.0);
    QVERIFY(h.mode == hatpic::ReferenceMode::Translation);
    QCOMPARE(h.ref_deadzone, true);
    QCOMPARE(h.tau_limit, 0.44);
}

void TestParams::defaultsValid()
{
    QVERIFY(hatpic::validate(DeviceParams{}).empty());
    QVERIFY(hatpic::validate(HostParams{}).empty());
    QCOMPARE(hatpic::firstViolatingField(DeviceParams{}), -1);
}

void TestParams::fieldAccessByIndex()
{
    DeviceParams p;
    const double values[] = {1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, values[i]);
    QCOMPARE(p.D_adm, 1.0);
    QCOMPARE(p.M_adm, 2.0);
    QCOMPARE(p.K_min, 3.0);
    QCOMPARE(p.K_max, 4.0);
    QCOMPARE(p.N, 5.0);
    QCOMPARE(p.Q_dz, 6.0);
    QCOMPARE(p.theta0, 7.0);
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        QCOMPARE(p.field(i), values[i]);
    QVERIFY(std::isnan(p.field(-1)));
    QVERIFY(std::isnan(p.field(7)));
    const DeviceParams before = p;
    p.setField(7, 99);
    p.setField(-1, 99);
    QVERIFY(p == before);
}

void TestParams::fieldNames()
{
    const char *const names[] = {"D_adm", "M_adm", "K_min", "K_max", "N", "Q_dz", "theta0"};
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        QCOMPARE(std::string(hatpic::deviceFieldName(i)), std::string(names[i]));
        QCOMPARE(hatpic::deviceFieldIndex(names[i]), i);
    }
    QVERIFY(hatpic::deviceFieldName(7).empty());
    QVERIFY(hatpic::deviceFieldName(-1).empty());
    QCOMPARE(hatpic::deviceFieldIndex("k_min"), -1);
    QCOMPARE(hatpic::deviceFieldIndex(""), -1);
    QCOMPARE(std::string(hatpic::referenceModeName(hatpic::ReferenceMode::Translation)),
             std::string("translation"));
    QCOMPARE(std::string(hatpic::referenceModeName(hatpic::ReferenceMode::Rotation)),
             std::string("rotation"));
}

// One row per rule of the device table: a value just outside the bound, and the exact message.
void TestParams::deviceRules_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");
    QTest::addColumn<QStringList>("expected");

    const double below1e6 = std::nextafter(1e-6, 0.0);
    const double halfPiUp = std::nextafter(std::numbers::pi / 2, 2.0);
    const double minusPiDown = std::nextafter(-std::numbers::pi, -4.0);
    const double piUp = std::nextafter(std::numbers::pi, 4.0);

    QTest::newRow("D_adm just below 1e-6")
        << 0 << below1e6 << QStringList{u"D_adm: must be ≥ 1e-06, got 9.999999999999997e-07"_s};
    QTest::newRow("D_adm zero") << 0 << 0.0 << QStringList{u"D_adm: must be ≥ 1e-06, got 0"_s};
    QTest::newRow("D_adm negative")
        << 0 << -1.0 << QStringList{u"D_adm: must be ≥ 1e-06, got -1"_s};
    QTest::newRow("D_adm just above 1")
        << 0 << std::nextafter(1.0, 2.0)
        << QStringList{u"D_adm: must be ≤ 1, got 1.0000000000000002"_s};
    QTest::newRow("M_adm zero (exclusive)")
        << 1 << 0.0 << QStringList{u"M_adm: must be > 0, got 0"_s};
    QTest::newRow("M_adm negative zero")
        << 1 << -0.0 << QStringList{u"M_adm: must be > 0, got -0"_s};
    QTest::newRow("M_adm negative")
        << 1 << -0.01 << QStringList{u"M_adm: must be > 0, got -0.01"_s};
    QTest::newRow("M_adm just above 10")
        << 1 << std::nextafter(10.0, 11.0)
        << QStringList{u"M_adm: must be ≤ 10, got 10.000000000000002"_s};
    QTest::newRow("K_min negative")
        << 2 << -1e-300 << QStringList{u"K_min: must be ≥ 0, got -1e-300"_s};
    QTest::newRow("K_min above K_max (cross-field, K_min's rule)")
        << 2 << std::nextafter(0.4, 1.0)
        << QStringList{u"K_min: must be ≤ K_max (0.4), got 0.4000000000000001"_s};
    QTest::newRow("K_max below K_min (reported on K_min)")
        << 3 << 0.1 << QStringList{u"K_min: must be ≤ K_max (0.1), got 0.15"_s};
    QTest::newRow("K_max negative") << 3 << -0.5
                                    << QStringList{u"K_min: must be ≤ K_max (-0.5), got 0.15"_s,
                                                   u"K_max: must be ≥ 0, got -0.5"_s};
    QTest::newRow("K_max just above 50")
        << 3 << std::nextafter(50.0, 51.0)
        << QStringList{u"K_max: must be ≤ 50, got 50.00000000000001"_s};
    QTest::newRow("N zero (exclusive)")
        << 4 << 0.0
        << QStringList{u"N: must be > 0, got 0"_s, u"Q_dz: must be < N (0), got 0.02"_s};
    QTest::newRow("N just above pi/2")
        << 4 << halfPiUp
        << QStringList{u"N: must be ≤ π/2 (1.5707963267948966), got 1.5707963267948968"_s};
    QTest::newRow("N at Q_dz (reported on Q_dz)")
        << 4 << 0.02 << QStringList{u"Q_dz: must be < N (0.02), got 0.02"_s};
    QTest::newRow("Q_dz negative")
        << 5 << -0.001 << QStringList{u"Q_dz: must be ≥ 0, got -0.001"_s};
    QTest::newRow("Q_dz equal to N (exclusive)")
        << 5 << 0.1 << QStringList{u"Q_dz: must be < N (0.1), got 0.1"_s};
    QTest::newRow("Q_dz above N") << 5 << 0.5 << QStringList{u"Q_dz: must be < N (0.1), got 0.5"_s};
    QTest::newRow("theta0 just below -pi")
        << 6 << minusPiDown
        << QStringList{u"theta0: must be ≥ −π (-3.141592653589793), got -3.1415926535897936"_s};
    QTest::newRow("theta0 just above pi")
        << 6 << piUp
        << QStringList{u"theta0: must be ≤ π (3.141592653589793), got 3.1415926535897936"_s};
}

void TestParams::deviceRules()
{
    QFETCH(int, index);
    QFETCH(double, value);
    QFETCH(QStringList, expected);
    const DeviceParams p = withField(index, value);
    QCOMPARE(messages(hatpic::validate(p)), expected);
}

void TestParams::deviceBoundariesAccepted_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");

    QTest::newRow("D_adm = 1e-6 (inclusive)") << 0 << 1e-6;
    QTest::newRow("D_adm = 1 (inclusive)") << 0 << 1.0;
    QTest::newRow("M_adm smallest positive") << 1 << std::numeric_limits<double>::denorm_min();
    QTest::newRow("M_adm = 10 (inclusive)") << 1 << 10.0;
    QTest::newRow("K_min = 0 (inclusive)") << 2 << 0.0;
    QTest::newRow("K_min = -0.0") << 2 << -0.0;
    QTest::newRow("K_min = K_max (inclusive)") << 2 << 0.4;
    QTest::newRow("K_max = K_min") << 3 << 0.15;
    QTest::newRow("K_max = 50 (inclusive)") << 3 << 50.0;
    QTest::newRow("N = pi/2 (inclusive)") << 4 << std::numbers::pi / 2;
    QTest::newRow("N just above Q_dz") << 4 << std::nextafter(0.02, 1.0);
    QTest::newRow("Q_dz = 0 (inclusive)") << 5 << 0.0;
    QTest::newRow("Q_dz just below N") << 5 << std::nextafter(0.1, 0.0);
    QTest::newRow("theta0 = -pi (inclusive)") << 6 << -std::numbers::pi;
    QTest::newRow("theta0 = pi (inclusive)") << 6 << std::numbers::pi;
}

void TestParams::deviceBoundariesAccepted()
{
    QFETCH(int, index);
    QFETCH(double, value);
    const DeviceParams p = withField(index, value);
    QVERIFY2(hatpic::validate(p).empty(), qPrintable(messages(hatpic::validate(p)).join(u'\n')));
    QCOMPARE(hatpic::firstViolatingField(p), -1);
}

void TestParams::nonFinite_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");
    QTest::addColumn<QStringList>("expected");

    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const QString name = QString::fromLatin1(hatpic::deviceFieldName(i).data());
        const std::pair<const char *, double> cases[] = {
            {"nan", kNaN}, {"inf", kInf}, {"-inf", -kInf}};
        for (const auto &[text, value] : cases) {
            QStringList expected{name + u": must be finite, got "_s + QLatin1String(text)};
            QTest::addRow("%s = %s", qPrintable(name), text) << i << value << expected;
        }
    }
}

// A non-finite value breaks exactly its own "must be finite" rule: its range rules and the
// cross-field rules that compare against it are not evaluated.
void TestParams::nonFinite()
{
    QFETCH(int, index);
    QFETCH(double, value);
    QFETCH(QStringList, expected);
    const DeviceParams p = withField(index, value);
    QCOMPARE(messages(hatpic::validate(p)), expected);
    QCOMPARE(hatpic::firstViolatingField(p), index);
}

void TestParams::multipleViolationsAllReported()
{
    DeviceParams p;
    p.D_adm = 2;    // > 1
    p.M_adm = kNaN; // not finite
    p.K_min = 1;    // > K_max
    p.K_max = 0.5;  // valid itself
    p.N = 0.05;     // valid itself
    p.Q_dz = 0.06;  // ≥ N
    p.theta0 = -4;  // < −π
    const auto violations = hatpic::validate(p);
    QCOMPARE(messages(violations),
             (QStringList{u"D_adm: must be ≤ 1, got 2"_s, u"M_adm: must be finite, got nan"_s,
                          u"K_min: must be ≤ K_max (0.5), got 1"_s,
                          u"Q_dz: must be < N (0.05), got 0.06"_s,
                          u"theta0: must be ≥ −π (-3.141592653589793), got -4"_s}));
    QCOMPARE(hatpic::firstViolatingField(p), 0);

    // Every field wrong at once: seven or more reports, in table order.
    DeviceParams all;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        all.setField(i, -100);
    QStringList fields;
    for (const auto &v : hatpic::validate(all))
        fields.append(QString::fromStdString(v.field));
    QCOMPARE(fields, (QStringList{u"D_adm"_s, u"M_adm"_s, u"K_min"_s, u"K_max"_s, u"N"_s, u"Q_dz"_s,
                                  u"Q_dz"_s, u"theta0"_s}));
}

void TestParams::firstViolatingFieldInTableOrder_data()
{
    QTest::addColumn<DeviceParams>("params");
    QTest::addColumn<int>("first");

    DeviceParams p;
    p.theta0 = 9;
    p.Q_dz = -1;
    QTest::newRow("Q_dz before theta0") << p << 5;
    p.K_min = 1; // > K_max: K_min's rule
    QTest::newRow("K_min (cross-field) before Q_dz") << p << 2;
    DeviceParams q;
    q.N = 0.01; // Q_dz = 0.02 ≥ N: Q_dz's rule, N itself is valid
    QTest::newRow("Q_dz < N belongs to Q_dz") << q << 5;
    DeviceParams r;
    r.K_max = 0.1; // K_min = 0.15 > K_max: K_min's rule, K_max itself is valid
    QTest::newRow("K_min <= K_max belongs to K_min") << r << 2;
    DeviceParams s;
    s.theta0 = kNaN;
    s.M_adm = 11;
    QTest::newRow("M_adm before theta0") << s << 1;
    DeviceParams t;
    t.theta0 = kInf;
    QTest::newRow("only theta0") << t << 6;
}

void TestParams::firstViolatingFieldInTableOrder()
{
    QFETCH(DeviceParams, params);
    QFETCH(int, first);
    QCOMPARE(hatpic::firstViolatingField(params), first);
    const auto violations = hatpic::validate(params);
    QVERIFY(!violations.empty());
    for (std::size_t i = 1; i < violations.size(); ++i)
        QVERIFY(violations[i - 1].index <= violations[i].index);
}

void TestParams::hostRules_data()
{
    QTest::addColumn<double>("v_max");
    QTest::addColumn<double>("tau_limit");
    QTest::addColumn<QStringList>("expected");

    QTest::newRow("defaults") << 1.0 << 0.44 << QStringList{};
    QTest::newRow("v_max smallest positive")
        << std::numeric_limits<double>::denorm_min() << 0.44 << QStringList{};
    QTest::newRow("upper bounds inclusive") << 100.0 << 10.0 << QStringList{};
    QTest::newRow("v_max zero (exclusive)")
        << 0.0 << 0.44 << QStringList{u"v_max: must be > 0, got 0"_s};
    QTest::newRow("v_max just above 100")
        << std::nextafter(100.0, 200.0) << 0.44
        << QStringList{u"v_max: must be ≤ 100, got 100.00000000000001"_s};
    QTest::newRow("v_max nan") << kNaN << 0.44 << QStringList{u"v_max: must be finite, got nan"_s};
    QTest::newRow("tau_limit zero (exclusive)")
        << 1.0 << 0.0 << QStringList{u"tau_limit: must be > 0, got 0"_s};
    QTest::newRow("tau_limit just above 10")
        << 1.0 << std::nextafter(10.0, 11.0)
        << QStringList{u"tau_limit: must be ≤ 10, got 10.000000000000002"_s};
    QTest::newRow("tau_limit -inf")
        << 1.0 << -kInf << QStringList{u"tau_limit: must be finite, got -inf"_s};
    QTest::newRow("both wrong") << -1.0 << 20.0
                                << QStringList{u"v_max: must be > 0, got -1"_s,
                                               u"tau_limit: must be ≤ 10, got 20"_s};
}

void TestParams::hostRules()
{
    QFETCH(double, v_max);
    QFETCH(double, tau_limit);
    QFETCH(QStringList, expected);
    HostParams h;
    h.v_max = v_max;
    h.tau_limit = tau_limit;
    QCOMPARE(messages(hatpic::validate(h)), expected);
    h.mode = hatpic::ReferenceMode::Rotation;
    h.ref_deadzone = false;
    QCOMPARE(messages(hatpic::validate(h)), expected);
}

void TestParams::violationCarriesFieldIndexRuleValue()
{
    DeviceParams p;
    p.K_min = 0.9;
    const auto v = hatpic::validate(p);
    QCOMPARE(v.size(), std::size_t(1));
    QCOMPARE(v[0].field, std::string("K_min"));
    QCOMPARE(v[0].index, 2);
    QCOMPARE(v[0].rule, std::string("must be ≤ K_max (0.4)"));
    QCOMPARE(v[0].value, 0.9);
    QCOMPARE(v[0].message(), std::string("K_min: must be ≤ K_max (0.4), got 0.9"));

    HostParams h;
    h.v_max = 0;
    const auto hv = hatpic::validate(h);
    QCOMPARE(hv.size(), std::size_t(1));
    QCOMPARE(hv[0].index, -1);
    QCOMPARE(hv[0].field, std::string("v_max"));
}

void TestParams::formatNumberShortestExact_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("0.4") << 0.4 << u"0.4"_s;
    QTest::newRow("1e-6") << 1e-6 << u"1e-06"_s;
    QTest::newRow("integer") << 50.0 << u"50"_s;
    QTest::newRow("negative zero") << -0.0 << u"-0"_s;
    QTest::newRow("pi") << std::numbers::pi << u"3.141592653589793"_s;
    QTest::newRow("0.1 + 0.2") << 0.1 + 0.2 << u"0.30000000000000004"_s;
    QTest::newRow("nan") << kNaN << u"nan"_s;
    QTest::newRow("inf") << kInf << u"inf"_s;
    QTest::newRow("-inf") << -kInf << u"-inf"_s;
}

void TestParams::formatNumberShortestExact()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    const std::string s = hatpic::formatNumber(value);
    QCOMPARE(QString::fromStdString(s), text);
    if (std::isfinite(value))
        QCOMPARE(std::strtod(s.c_str(), nullptr), value);
}

void TestParams::roundedForWireKeepsBounds_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");
    constexpr double pi = std::numbers::pi;
    QTest::newRow("D_adm = 1e-6 (float rounds below)") << 0 << 1e-6;
    QTest::newRow("D_adm = 1 (exact)") << 0 << 1.0;
    QTest::newRow("M_adm = 1e-300 (float rounds to 0)") << 1 << 1e-300;
    QTest::newRow("N = pi/2 (float rounds above)") << 4 << pi / 2;
    QTest::newRow("theta0 = pi") << 6 << pi;
    QTest::newRow("theta0 = -pi") << 6 << -pi;
    QTest::newRow("K_max = 0.4 (ordinary value)") << 3 << 0.4;
}

void TestParams::roundedForWireKeepsBounds()
{
    QFETCH(int, index);
    QFETCH(double, value);
    hatpic::DeviceParams p;
    if (index == 4)
        p.Q_dz = 0.02;
    p.setField(index, value);
    QVERIFY(hatpic::validate(p).empty());

    const hatpic::DeviceParams wire = hatpic::roundedForWire(p);
    // Every field is a float, the set is still valid, and no field moved more than one float.
    for (int i = 0; i < hatpic::DeviceParams::kFieldCount; ++i) {
        const float f = static_cast<float>(wire.field(i));
        QCOMPARE(static_cast<double>(f), wire.field(i));
        const float nearest = static_cast<float>(p.field(i));
        QVERIFY2(f == nearest || std::nextafter(nearest, f) == f || (i == 1 && nearest == 0.0f),
                 qPrintable(QString::number(i)));
    }
    const auto violations = hatpic::validate(wire);
    QVERIFY2(violations.empty(), violations.empty() ? "" : violations.front().message().c_str());
}

void TestParams::roundedForWireKeepsInvalidInvalid()
{
    hatpic::DeviceParams p;
    p.K_max = 60; // outside: must stay outside so the device refuses it
    p.Q_dz = p.N; // cross-field violation stays
    const auto violations = hatpic::validate(hatpic::roundedForWire(p));
    QCOMPARE(violations.size(), std::size_t(2));
    QCOMPARE(violations[0].field, std::string("K_max"));
    QCOMPARE(violations[1].field, std::string("Q_dz"));
}

void TestParams::shortestFloatDecimal_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("expected");
    QTest::newRow("0.44f becomes 0.44") << double(0.44f) << 0.44;
    QTest::newRow("0.4f becomes 0.4") << double(0.4f) << 0.4;
    QTest::newRow("1e-4f becomes 1e-4") << double(1e-4f) << 1e-4;
    QTest::newRow("exact float 0.5 stays") << 0.5 << 0.5;
    QTest::newRow("not a float: unchanged") << 0.1 << 0.1;
    QTest::newRow("pi (not a float): unchanged") << std::numbers::pi << std::numbers::pi;
    QTest::newRow("infinity: unchanged") << kInf << kInf;
}

void TestParams::shortestFloatDecimal()
{
    QFETCH(double, value);
    QFETCH(double, expected);
    QCOMPARE(hatpic::shortestFloatDecimal(value), expected);
    // Whatever it returns still names the same float.
    QCOMPARE(static_cast<float>(hatpic::shortestFloatDecimal(value)), static_cast<float>(value));
}

QTEST_GUILESS_MAIN(TestParams)
#include "tst_params.moc"
