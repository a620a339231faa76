// BlindStudy: the seeded, balanced order; answers and response times; the binomial score; the
// trials file (header, columns, rows) written atomically.
#include "study/blindstudy.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

namespace {

BlindSetup setup(int trials, quint64 seed)
{
    BlindSetup s;
    s.trials = trials;
    s.seed = seed;
    s.profileA = QStringLiteral("Soft");
    s.profileB = QStringLiteral("Soft, stiffer\nnotch");
    s.question = QStringLiteral("Which felt stiffer?");
    return s;
}

QDateTime at(double seconds)
{
    return QDateTime(QDate(2026, 11, 22), QTime(23, 0), Qt::UTC).addMSecs(qint64(seconds * 1000));
}

} // namespace

class TestBlindStudy : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sequenceIsBalancedAndSeeded_data();
    void sequenceIsBalancedAndSeeded();
    void seedsGiveDifferentOrders();
    void setupIsChecked_data();
    void setupIsChecked();
    void answersMoveThroughTheTrials();
    void scoreIsAnExactBinomialTest_data();
    void scoreIsAnExactBinomialTest();
    void csvHoldsHeaderAndAnsweredTrials();
    void writeIsAtomicAndReportsFailure();
};

void TestBlindStudy::sequenceIsBalancedAndSeeded_data()
{
    QTest::addColumn<int>("trials");
    for (int n : {1, 2, 7, 10, 101, BlindStudy::kMaxTrials})
        QTest::addRow("%d trials", n) << n;
}

void TestBlindStudy::sequenceIsBalancedAndSeeded()
{
    QFETCH(int, trials);
    const auto orders = BlindStudy::sequence(trials, 42);
    QCOMPARE(orders.size(), trials);
    int ab = 0;
    for (const auto &o : orders) {
        QVERIFY(o[0] != o[1]);
        ab += o[0] == 0 ? 1 : 0;
    }
    QVERIFY2(std::abs(2 * ab - trials) <= 1, qPrintable(QString::number(ab)));
    QCOMPARE(BlindStudy::sequence(trials, 42), orders); // the seed decides
}

void TestBlindStudy::seedsGiveDifferentOrders()
{
    // The first 20 seeds: every one gives a valid order, and they are not all alike.
    QSet<QString> seen;
    for (quint64 seed = 0; seed < 20; ++seed) {
        QString text;
        for (const auto &o : BlindStudy::sequence(16, seed))
            text += BlindStudy::orderText(o);
        seen.insert(text);
    }
    QVERIFY2(seen.size() > 15, qPrintable(QString::number(seen.size())));
}

void TestBlindStudy::setupIsChecked_data()
{
    QTest::addColumn<int>("trials");
    QTest::addColumn<QString>("question");
    QTest::addColumn<QString>("error");
    QTest::newRow("fine") << 10 << QStringLiteral("Which?") << QString();
    QTest::newRow("no trials") << 0 << QStringLiteral("Which?")
                               << QStringLiteral("trials: must be 1 … 1000, got 0");
    QTest::newRow("too many") << 1001 << QStringLiteral("Which?")
                              << QStringLiteral("trials: must be 1 … 1000, got 1001");
    QTest::newRow("no question") << 4 << QStringLiteral("  ")
                                 << QStringLiteral("question: must not be empty");
}

void TestBlindStudy::setupIsChecked()
{
    QFETCH(int, trials);
    QFETCH(QString, question);
    QFETCH(QString, error);
    BlindSetup s = setup(trials, 1);
    s.question = question;
    QCOMPARE(BlindStudy::check(s), error);
}

void TestBlindStudy::answersMoveThroughTheTrials()
{
    BlindStudy study(setup(3, 7));
    QCOMPARE(study.trials().size(), 3);
    QCOMPARE(study.current()->number, 1);
    study.markPresented(at(0));
    QVERIFY(!study.answer(3, 1.0, at(1))); // no such interval: nothing changes
    QCOMPARE(study.answeredCount(), 0);
    QVERIFY(study.answer(2, 1.25, at(2)));
    const BlindTrial &first = study.trials()[0];
    QCOMPARE(first.answer, 2);
    QCOMPARE(first.answeredSlot(), first.order[1]);
    QCOMPARE(first.responseSeconds, 1.25);
    QCOMPARE(study.current()->number, 2);
    QVERIFY(study.answer(1, 0.5, at(3)));
    QVERIFY(study.answer(1, 0.5, at(4)));
    QVERIFY(study.isFinished());
    QCOMPARE(study.current(), nullptr);
    QVERIFY(!study.answer(1, 0.5, at(5)));
    QCOMPARE(study.answeredCount(), 3);
}

void TestBlindStudy::scoreIsAnExactBinomialTest_data()
{
    QTest::addColumn<int>("trials");
    QTest::addColumn<int>("chooseB"); // how many of them are answered with slot B
    QTest::addColumn<double>("p");
    QTest::newRow("10 of 10") << 10 << 10 << 2.0 / 1024;
    QTest::newRow("0 of 10") << 10 << 0 << 2.0 / 1024;
    QTest::newRow("5 of 10") << 10 << 5 << 1.0;
    QTest::newRow("8 of 10") << 10 << 8 << 2.0 * (1 + 10 + 45) / 1024;
    QTest::newRow("1 of 1") << 1 << 1 << 1.0;
}

void TestBlindStudy::scoreIsAnExactBinomialTest()
{
    QFETCH(int, trials);
    QFETCH(int, chooseB);
    QFETCH(double, p);
    BlindStudy study(setup(trials, 3));
    QCOMPARE(study.score().pValue, 1.0);
    for (int i = 0; i < trials; ++i) {
        const BlindTrial *t = study.current();
        const int wanted = i < chooseB ? 1 : 0;
        QVERIFY(study.answer(t->order[0] == wanted ? 1 : 2, 1.0, at(i)));
    }
    const BlindStudy::Score s = study.score();
    QCOMPARE(s.answered, trials);
    QCOMPARE(s.chosenB, chooseB);
    QVERIFY2(std::abs(s.pValue - p) < 1e-12, qPrintable(QString::number(s.pValue)));
}

void TestBlindStudy::csvHoldsHeaderAndAnsweredTrials()
{
    BlindStudy study(setup(4, 99));
    const auto orders = BlindStudy::sequence(4, 99);
    study.markPresented(at(10));
    QVERIFY(study.answer(1, 2.5, at(13)));
    study.markPresented(at(20));
    QVERIFY(study.answer(2, 0.1234, at(21)));

    const QStringList lines = QString::fromUtf8(study.csv()).split(u'\n');
    QVERIFY(lines[0].startsWith(QStringLiteral("# HATPIC blind A/B study")));
    QCOMPARE(lines[1], QStringLiteral("# profile A: Soft"));
    QCOMPARE(lines[2], QStringLiteral("# profile B: Soft, stiffer notch")); // one line
    QCOMPARE(lines[3], QStringLiteral("# seed: 99"));
    QCOMPARE(lines[4], QStringLiteral("# trials: 4"));
    QCOMPARE(lines[5], QStringLiteral("# question: Which felt stiffer?"));
    QCOMPARE(lines[6], QLatin1StringView(BlindStudy::kColumns));
    QCOMPARE(lines[7],
             QStringLiteral("1,%1,1,%2,2.500,2026-11-22T23:00:10.000Z,"
                            "2026-11-22T23:00:13.000Z")
                 .arg(BlindStudy::orderText(orders[0]), BlindStudy::slotName(orders[0][0])));
    QCOMPARE(lines[8],
             QStringLiteral("2,%1,2,%2,0.123,2026-11-22T23:00:20.000Z,"
                            "2026-11-22T23:00:21.000Z")
                 .arg(BlindStudy::orderText(orders[1]), BlindStudy::slotName(orders[1][1])));
    QCOMPARE(lines[9], QString()); // the unanswered trials have no row
    QCOMPARE(lines.size(), 10);
}

void TestBlindStudy::writeIsAtomicAndReportsFailure()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    BlindStudy study(setup(2, 5));
    const QString path = dir.filePath(QStringLiteral("trials.csv"));
    QCOMPARE(study.writeCsv(path), QString());
    QVERIFY(study.answer(1, 1.0, at(1)));
    QCOMPARE(study.writeCsv(path), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), study.csv());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("trials.csv")});

    const QString bad = dir.filePath(QStringLiteral("no/such/dir/trials.csv"));
    const QString error = study.writeCsv(bad);
    QVERIFY(error.startsWith(QStringLiteral("cannot write ")));
    QVERIFY(!QFile::exists(bad));
}

QTEST_GUILESS_MAIN(TestBlindStudy)
#include "tst_blindstudy.moc"
