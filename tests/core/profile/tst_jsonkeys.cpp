// firstDuplicateKey on a large, deeply nested file: its memory stays linear in the file
// (issue 27: a path string per open level made a 1 MiB profile cost 1 GB). Its own program,
// so that the process's peak resident memory before the scan is the scan's baseline.
#include "profile/jsonfile.h"
#include "profile/jsonkeys.h"
#include "profile/profile.h"

#include <QtTest>

#include <sys/resource.h>

using namespace Qt::StringLiterals;

namespace {

qint64 peakRssBytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<qint64>(usage.ru_maxrss) * 1024;
}

//! {"kkk…0": {"kkk…1": … {"x": 1, "x": 2} …}}: `depth` levels, each key `keyLength` long.
QByteArray nested(int depth, int keyLength, bool duplicateInside)
{
    QByteArray json;
    json.reserve(depth * (keyLength + 16) + 64);
    for (int d = 0; d < depth; ++d) {
        QByteArray key = QByteArray::number(d);
        key.prepend(QByteArray(keyLength - key.size(), 'k'));
        json += "{\"" + key + "\":";
    }
    json += duplicateInside ? "{\"x\":1,\"x\":2}" : "{\"x\":1}";
    json += QByteArray(depth, '}');
    return json;
}

} // namespace

class TestJsonKeys : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void deepProfileCostsLinearMemory();
    void duplicateDeepInsideIsNamedWithItsPath();
};

void TestJsonKeys::deepProfileCostsLinearMemory()
{
    // 1000 levels (QJsonDocument's nesting limit is 1024) of 1000-character keys: 1 MB, just
    // under a profile's 1 MiB. A path per level held 1000²/2 keys' worth of text: about 1 GB.
    const QByteArray json = nested(1000, 1000, false);
    QVERIFY(json.size() < hatpic::kMaxProfileBytes);
    const qint64 before = peakRssBytes();
    const hatpic::ProfileReadResult result = hatpic::parseProfile(json);
    const qint64 grown = peakRssBytes() - before;
    // Refused as a profile (not the format), but read and scanned: no duplicate to report.
    QVERIFY(!result.ok());
    QVERIFY(hatpic::firstDuplicateKey(json).isEmpty());
    const qint64 limit = 64LL << 20;
    QVERIFY2(grown < limit,
             qPrintable(u"peak memory grew by %1 MiB reading a 1 MB profile"_s.arg(grown >> 20)));
    qInfo("peak RSS grew by %.1f MiB (file %.2f MiB)", grown / 1048576.0, json.size() / 1048576.0);
}

void TestJsonKeys::duplicateDeepInsideIsNamedWithItsPath()
{
    const QByteArray json = nested(3, 2, true);
    QCOMPARE(hatpic::firstDuplicateKey(json), u"k0.k1.k2.x"_s);
    QCOMPARE(hatpic::firstDuplicateKey(R"({"a": [[{"b": 1, "b": 2}]]})"), u"a[][].b"_s);
    QCOMPARE(hatpic::firstDuplicateKey(R"([{"a": 1, "a": 2}])"), u"[].a"_s);
}

QTEST_GUILESS_MAIN(TestJsonKeys)
#include "tst_jsonkeys.moc"
