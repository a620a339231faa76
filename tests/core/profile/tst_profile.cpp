// Tests for profile files (profile.md): exact writing, atomic saves, reading files safely. The
// reading rules (what a document must hold): tst_profilerules; the presets: tst_profilepresets.

#include "profile/paramsjson.h"
#include "profile/profile.h"
#include "readback.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>
#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

using namespace Qt::Literals::StringLiterals;

namespace {

using hatpic::Profile;
using hatpic::test::identical;
using hatpic::test::readAll;
using hatpic::test::readsBackAs;

// Number of seeded random cases; raise with HATPIC_RANDOM_CASES=100000.
int randomCases()
{
    const int n = qEnvironmentVariableIntValue("HATPIC_RANDOM_CASES");
    return n > 0 ? n : 5000;
}

// Random doubles with full 53-bit mantissas spread over all binary exponents of [lo, hi].
class RandomDoubles
{
public:
    explicit RandomDoubles(std::uint64_t seed) : m_engine(seed) {}

    // Positive value in [lo, hi] (lo > 0); log-uniform exponent, random mantissa.
    double in(double lo, double hi)
    {
        std::uniform_int_distribution<int> exp(std::ilogb(lo), std::ilogb(hi));
        for (;;) {
            const double mantissa =
                std::bit_cast<double>((m_engine() >> 12) | 0x3ff0000000000000ULL); // [1, 2)
            const double v = std::ldexp(mantissa, exp(m_engine));
            if (v >= lo && v <= hi)
                return v;
        }
    }
    // In [0, hi]: sometimes exactly 0, −0.0, the smallest subnormal or hi itself.
    double zeroTo(double hi)
    {
        switch (m_engine() % 10) {
        case 0:
            return 0.0;
        case 1:
            return -0.0;
        case 2:
            return std::numeric_limits<double>::denorm_min();
        case 3:
            return hi;
        default:
            return in(std::numeric_limits<double>::denorm_min(), hi);
        }
    }
    bool coin() { return m_engine() % 2 == 0; }
    std::uint64_t bits() { return m_engine(); }

    QString text()
    {
        static const char16_t *const kPieces[] = {
            u"a", u"Zz", u" ", u"\"", u"\\",     u"/",  u"\n", u"\t", u"\u0001", u"\u001f",
            u"é", u"π",  u"→", u"😀",  u"\u2028", u"{}", u"[",  u",",  u"\u007f", u"0.1"};
        QString out;
        const int count = static_cast<int>(m_engine() % 12);
        for (int i = 0; i < count; ++i)
            out += QString::fromUtf16(kPieces[m_engine() % std::size(kPieces)]);
        return out;
    }

private:
    std::mt19937_64 m_engine;
};

Profile randomValidProfile(RandomDoubles &r)
{
    Profile p;
    p.name = r.text();
    p.notes = r.text();
    p.device.D_adm = r.in(1e-6, 1.0);
    p.device.M_adm = r.in(std::numeric_limits<double>::denorm_min(), 10.0);
    p.device.K_max = r.zeroTo(50.0);
    p.device.K_min = std::abs(p.device.K_max) > 0 ? r.zeroTo(p.device.K_max) : p.device.K_max;
    p.device.N = r.in(std::numeric_limits<double>::denorm_min(), std::numbers::pi / 2);
    do {
        p.device.Q_dz = r.zeroTo(p.device.N);
    } while (!(p.device.Q_dz < p.device.N));
    p.device.theta0 = r.coin() ? r.zeroTo(std::numbers::pi) : -r.zeroTo(std::numbers::pi);
    p.host.v_max = r.in(std::numeric_limits<double>::denorm_min(), 100.0);
    p.host.tau_limit = r.in(std::numeric_limits<double>::denorm_min(), 10.0);
    p.host.mode = r.coin() ? hatpic::ReferenceMode::Translation : hatpic::ReferenceMode::Rotation;
    p.host.ref_deadzone = r.coin();
    // The bridge's limit within that tau_limit (bridge::limitProblem()).
    p.bridge.feedback.limit = std::min(p.bridge.feedback.limit, p.host.tau_limit);
    return p;
}

Profile namedDefault(const QString &name)
{
    Profile p;
    p.name = name;
    return p;
}

} // namespace

class TestProfile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void serializedTextExact();
    void jsonNumberText_data();
    void jsonNumberText();
    void jsonNumberRoundTripAllDoubles();
    void profileRoundTripExact();
    void writeThenRead();
    void writeFailureKeepsExistingFile_data();
    void writeFailureKeepsExistingFile();
    void writeFailureDiskFull_data();
    void writeFailureDiskFull();
    void writeFailureReadOnlyDirectory();
    void readMissingFile();
    void readDirectory();
    void readPipeRefused();
    void readSizeLimit();
    void readEndlessFileStopsAtLimit();
};

void TestProfile::serializedTextExact()
{
    Profile p;
    p.name = u"Default"_s;
    p.notes = u"free text"_s;
    const QByteArray expected = "{\n"
                                "  \"format\": \"hatpic-profile\",\n"
                                "  \"version\": 1,\n"
                                "  \"name\": \"Default\",\n"
                                "  \"notes\": \"free text\",\n"
                                "  \"device\": {\n"
                                "    \"D_adm\": 0.0001,\n"
                                "    \"M_adm\": 0.01,\n"
                                "    \"K_min\": 0.15,\n"
                                "    \"K_max\": 0.4,\n"
                                "    \"N\": 0.1,\n"
                                "    \"Q_dz\": 0.02,\n"
                                "    \"theta0\": 0.0\n"
                                "  },\n"
                                "  \"host\": {\n"
                                "    \"mode\": \"translation\",\n"
                                "    \"v_max\": 1.0,\n"
                                "    \"ref_deadzone\": true,\n"
                                "    \"tau_limit\": 0.44\n"
                                "  }\n"
                                "}\n";
    QCOMPARE(hatpic::serializeProfile(p), expected);

    // Strings are escaped as JSON requires; everything else is plain UTF-8.
    p.name = u"a\"b\\c/d\né\u0001😀"_s;
    p.notes.clear();
    p.host.mode = hatpic::ReferenceMode::Rotation;
    p.host.ref_deadzone = false;
    const QByteArray text = hatpic::serializeProfile(p);
    QVERIFY(text.contains("  \"name\": \"a\\\"b\\\\c/d\\n\xc3\xa9\\u0001\xf0\x9f\x98\x80\",\n"));
    QVERIFY(text.contains("  \"notes\": \"\",\n"));
    QVERIFY(text.contains("    \"mode\": \"rotation\",\n"));
    QVERIFY(text.contains("    \"ref_deadzone\": false,\n"));
}

void TestProfile::jsonNumberText_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QByteArray>("text");

    QTest::newRow("zero") << 0.0 << QByteArray("0.0");
    QTest::newRow("negative zero is written as zero") << -0.0 << QByteArray("0.0");
    QTest::newRow("one") << 1.0 << QByteArray("1.0");
    QTest::newRow("minus forty") << -40.0 << QByteArray("-40.0");
    QTest::newRow("0.44") << 0.44 << QByteArray("0.44");
    QTest::newRow("0.0001") << 0.0001 << QByteArray("0.0001");
    QTest::newRow("1e-5 still fixed") << 1e-5 << QByteArray("0.00001");
    QTest::newRow("1e-6 exponent") << 1e-6 << QByteArray("1e-6");
    QTest::newRow("pi") << std::numbers::pi << QByteArray("3.141592653589793");
    QTest::newRow("123.456") << 123.456 << QByteArray("123.456");
    QTest::newRow("1e15 fixed") << 1e15 << QByteArray("1000000000000000.0");
    QTest::newRow("1e16 exponent") << 1e16 << QByteArray("1e16");
    QTest::newRow("-1.5e300") << -1.5e300 << QByteArray("-1.5e300");
    QTest::newRow("smallest subnormal")
        << std::numeric_limits<double>::denorm_min() << QByteArray("5e-324");
    QTest::newRow("largest") << std::numeric_limits<double>::max()
                             << QByteArray("1.7976931348623157e308");
    QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << QByteArray("null");
    QTest::newRow("inf") << std::numeric_limits<double>::infinity() << QByteArray("null");
}

void TestProfile::jsonNumberText()
{
    QFETCH(double, value);
    QFETCH(QByteArray, text);
    QCOMPARE(hatpic::jsonNumber(value), text);
}

// The writer's numbers read back bit-identical through Qt's JSON reader, over all finite doubles.
void TestProfile::jsonNumberRoundTripAllDoubles()
{
    RandomDoubles r(20240611);
    const int cases = randomCases() * 4;
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  9007199254740992.0,
                                  9007199254740994.0,
                                  1e15,
                                  1e16,
                                  123456789012345680000.0,
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::lowest(),
                                  std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::denorm_min()};
    while (values.size() < static_cast<std::size_t>(cases)) {
        const double v = std::bit_cast<double>(r.bits());
        if (std::isfinite(v))
            values.push_back(v);
    }
    for (double v : values) {
        const QByteArray text = hatpic::jsonNumber(v);
        QVERIFY2(text.contains('.') || text.contains('e'), text.constData());
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson("[" + text + "]", &error);
        QVERIFY2(error.error == QJsonParseError::NoError, text.constData());
        const double back = doc.array().at(0).toDouble();
        QVERIFY2(readsBackAs(back, v), text.constData());
    }
}

void TestProfile::profileRoundTripExact()
{
    RandomDoubles r(7);
    const int cases = randomCases();
    for (int i = 0; i < cases; ++i) {
        const Profile p = randomValidProfile(r);
        QVERIFY(hatpic::validate(p.device).empty());
        QVERIFY(hatpic::validate(p.host).empty());
        const QByteArray text = hatpic::serializeProfile(p);
        const auto result = hatpic::parseProfile(text);
        QVERIFY2(result.ok(),
                 qPrintable(result.errors.join(u'\n') + u'\n' + QString::fromUtf8(text)));
        QVERIFY(result.warnings.isEmpty());
        QVERIFY2(identical(*result.profile, p), text.constData());
        // Writing what was read gives the same bytes.
        QCOMPARE(hatpic::serializeProfile(*result.profile), text);
    }
}

void TestProfile::writeThenRead()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"tuning.json"_s);
    Profile p = namedDefault(u"Mine"_s);
    p.device.K_max = 0.7;
    p.device.theta0 = -0.25;
    QCOMPARE(hatpic::writeProfile(p, path), QString());
    QCOMPARE(readAll(path), hatpic::serializeProfile(p));
    const auto result = hatpic::readProfile(path);
    QVERIFY2(result.ok(), qPrintable(result.errors.join(u'\n')));
    QVERIFY(identical(*result.profile, p));

    // Overwriting replaces the whole content.
    p.name = u"x"_s;
    QCOMPARE(hatpic::writeProfile(p, path), QString());
    QCOMPARE(readAll(path), hatpic::serializeProfile(p));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"tuning.json"_s});
}

void TestProfile::writeFailureKeepsExistingFile_data()
{
    QTest::addColumn<QString>("target"); // relative to the temporary directory
    QTest::addColumn<bool>("invalidProfile");
    QTest::addColumn<QString>("error"); // with "%1" for the absolute target path

    QTest::newRow("path is a directory")
        << u"adir"_s << false << u"cannot write profile \"%1\": Filename refers to a directory"_s;
    QTest::newRow("parent directory missing")
        << u"missing/good.json"_s << false
        << u"cannot write profile \"%1\": No such file or directory"_s;
    QTest::newRow("invalid profile refused")
        << u"good.json"_s << true
        << u"refusing to write an invalid profile to \"%1\": device.K_min: must be ≤ K_max "
           u"(0.4), got 0.9; host.v_max: must be > 0, got -1"_s;
}

void TestProfile::writeFailureKeepsExistingFile()
{
    QFETCH(QString, target);
    QFETCH(bool, invalidProfile);
    QFETCH(QString, error);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(u"adir"_s));
    const QString good = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), good), QString());
    const QByteArray before = readAll(good);
    QVERIFY(!before.isEmpty());

    Profile p = namedDefault(u"Other"_s);
    if (invalidProfile) {
        p.device.K_min = 0.9;
        p.host.v_max = -1;
    }
    const QString path = dir.filePath(target);
    QCOMPARE(hatpic::writeProfile(p, path), error.arg(path));
    QCOMPARE(readAll(good), before);
    QVERIFY(QFileInfo(dir.filePath(u"adir"_s)).isDir());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"good.json"_s});
}

// A write that fails half-way (here: the file-size limit, as on a full disk) leaves the old
// file byte-identical and no temporary file behind. Works as root too.
void TestProfile::writeFailureDiskFull_data()
{
    QTest::addColumn<int>("notesSize");
    // QFileDevice buffers small writes: the first row fails only when commit() flushes, the
    // second already in write(), which bypasses the 16 KiB buffer for large blocks.
    QTest::newRow("fails on commit") << 4000;
    QTest::newRow("fails on write") << 40000;
}

void TestProfile::writeFailureDiskFull()
{
    QFETCH(int, notesSize);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), path), QString());
    const QByteArray before = readAll(path);

    Profile big = namedDefault(u"Big"_s);
    big.notes = QString(notesSize, u'n');

    rlimit old{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = old;
    limited.rlim_cur = 1000; // bytes: less than the profile being written
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &limited), 0);
    const QString error = hatpic::writeProfile(big, path);
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &old), 0);
    std::signal(SIGXFSZ, oldHandler);

    QCOMPARE(error, u"cannot write profile \""_s + path + u"\": File too large"_s);
    QCOMPARE(readAll(path), before);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"good.json"_s});
}

void TestProfile::writeFailureReadOnlyDirectory()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"good.json"_s);
    QCOMPARE(hatpic::writeProfile(namedDefault(u"Good"_s), path), QString());
    const QByteArray before = readAll(path);
    QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
    const bool canStillCreate = QFile(dir.filePath(u"probe"_s)).open(QIODevice::WriteOnly);
    if (canStillCreate) {
        QFile::remove(dir.filePath(u"probe"_s));
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QSKIP("permissions are not enforced for this user (root); see writeFailureDiskFull");
    }
    const QString error = hatpic::writeProfile(namedDefault(u"Other"_s), path);
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(error.startsWith(u"cannot write profile \""_s + path + u"\": "_s));
    QCOMPARE(readAll(path), before);
}

void TestProfile::readMissingFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"nowhere.json"_s);
    const auto result = hatpic::readProfile(path);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors,
             QStringList{u"cannot open profile \""_s + path + u"\": No such file or directory"_s});
}

void TestProfile::readDirectory()
{
    QTemporaryDir dir;
    const auto result = hatpic::readProfile(dir.path());
    QVERIFY(!result.ok());
    QCOMPARE(result.errors,
             QStringList{u"profile \""_s + dir.path() + u"\" is a folder, not a file"_s});
}

// A pipe would block the open until a writer comes: it is refused before (issue 21).
void TestProfile::readPipeRefused()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"fifo"_s);
    QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    const auto result = hatpic::readProfile(path);
    QCOMPARE(result.errors, QStringList{u"profile \""_s + path +
                                        u"\" is not a regular file (a device or a pipe); "
                                        u"refused"_s});
}

void TestProfile::readSizeLimit()
{
    QTemporaryDir dir;
    const QByteArray text = hatpic::serializeProfile(namedDefault(u"Padded"_s));
    const QString path = dir.filePath(u"p.json"_s);

    // Exactly 1 MiB (whitespace padding is valid JSON) is accepted.
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(text);
        file.write(QByteArray(hatpic::kMaxProfileBytes - text.size(), ' '));
    }
    QCOMPARE(QFileInfo(path).size(), hatpic::kMaxProfileBytes);
    const auto accepted = hatpic::readProfile(path);
    QVERIFY2(accepted.ok(), qPrintable(accepted.errors.join(u'\n')));

    // One byte more is refused.
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::Append));
        file.write(" ");
    }
    const auto refused = hatpic::readProfile(path);
    QVERIFY(!refused.ok());
    QCOMPARE(refused.errors, QStringList{u"profile \""_s + path +
                                         u"\" is larger than 1 MiB (1048576 bytes), got "
                                         u"1048577 bytes; refused"_s});
}

// /dev/zero never ends and reports size 0: it is not read at all.
void TestProfile::readEndlessFileStopsAtLimit()
{
    if (!QFileInfo::exists(u"/dev/zero"_s))
        QSKIP("no /dev/zero");
    const auto result = hatpic::readProfile(u"/dev/zero"_s);
    QVERIFY(!result.ok());
    QCOMPARE(result.errors, QStringList{u"profile \"/dev/zero\" is not a regular file (a device "
                                        u"or a pipe); refused"_s});
}

QTEST_GUILESS_MAIN(TestProfile)
#include "tst_profile.moc"
