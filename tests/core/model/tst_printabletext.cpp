// The one rule for foreign text (issue 27): control characters shown as escapes, the rest kept.
#include "model/params.h"
#include "model/printabletext.h"

#include <QTest>

using namespace hatpic;

class TestPrintableText : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void controlCharactersBecomeEscapes_data();
    void controlCharactersBecomeEscapes();
    void echoedTextIsPrintableAndCut();
};

void TestPrintableText::controlCharactersBecomeEscapes_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QByteArray>("printable");
    QTest::newRow("clear screen") << QByteArray("\x1b[2Jhi") << QByteArray("\\x1b[2Jhi");
    QTest::newRow("window title") << QByteArray("\x1b]0;owned\x07")
                                  << QByteArray("\\x1b]0;owned\\x07");
    QTest::newRow("fake line") << QByteArray("a\r\nb\tc") << QByteArray("a\\x0d\\x0ab\\x09c");
    QTest::newRow("DEL and NUL") << QByteArray("x\x7fy", 3) + QByteArray(1, '\0')
                                 << QByteArray("x\\x7fy\\x00");
    QTest::newRow("C1 CSI") << QByteArray("\xc2\x9b"
                                          "2J")
                            << QByteArray("\\x9b2J");
    QTest::newRow("UTF-8 kept") << QByteArray("τ_ext é ±π … \xc2\xa0")
                                << QByteArray("τ_ext é ±π … \xc2\xa0");
}

void TestPrintableText::controlCharactersBecomeEscapes()
{
    QFETCH(QByteArray, text);
    QFETCH(QByteArray, printable);
    QCOMPARE(QByteArray::fromStdString(printableText(text.toStdString())), printable);
}

void TestPrintableText::echoedTextIsPrintableAndCut()
{
    QCOMPARE(echoedText("\x1b[2J"), std::string("\\x1b[2J"));
    const std::string longKey = "\x1b" + std::string(200, 'k');
    const std::string echoed = echoedText(longKey);
    QVERIFY(echoed.starts_with("\\x1bkkk"));
    QVERIFY(echoed.ends_with("… (201 bytes)"));
    QVERIFY(echoed.find('\x1b') == std::string::npos);
}

QTEST_GUILESS_MAIN(TestPrintableText)
#include "tst_printabletext.moc"
