// hatpicctl teleop-map as a real process: the table on stdout, the CSV's columns and rows, the
// SVG and the PNG (drawn without a display), ranges, a tuning field varied; bad options and
// output targets refused before anything runs (exit 4, naming option, rule and value), an
// existing file kept without --force.
#include "ctlprocess.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic::test;

class TestHatpicctlTeleopMap : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tableCsvAndSvg();
    void pngWithoutADisplay();
    void variesAField();
    void controllerOffAndOn();
    void handsAndContacts();
    void badOptions_data();
    void badOptions();
    void keepsAnExistingFile();
};

void TestHatpicctlTeleopMap::tableCsvAndSvg()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"map.csv"_s), svg = dir.filePath(u"map.svg"_s);
    const Run run =
        runCtl({u"teleop-map"_s, u"--delays"_s, u"0,0.15"_s, u"--gains"_s, u"0.02"_s, u"--pc"_s,
                u"0"_s, u"--duration"_s, u"8"_s, u"--csv"_s, csv, u"--svg"_s, svg});
    QVERIFY2(run.code == 0, run.err.constData());
    const QList<QByteArray> lines = run.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    QVERIFY(lines[0].contains("settled") && lines[0].contains("settle_s"));
    QVERIFY2(lines[1].simplified().startsWith("0.000 0.0200 0.000 1 "), lines[1].constData());
    QVERIFY2(lines[2].simplified().startsWith("0.150 0.0200 0.000 0 - "), lines[2].constData());
    QVERIFY(run.err.contains("2 cells of 8 s in "));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = file.readAll().trimmed().split('\n');
    QCOMPARE(rows.size(), 3);
    QVERIFY(rows[0].startsWith(
        "delay,gain,pc,settled,settle_s,p2p,rms_tau_pc_ratio,dissipated_j,theta_rest,"));
    QVERIFY(rows[1].startsWith("0,0.02,0,1,"));
    QVERIFY(rows[2].startsWith("0.15,0.02,0,0,,"));
    QFile chart(svg);
    QVERIFY(chart.open(QIODevice::ReadOnly));
    const QByteArray image = chart.readAll();
    QVERIFY(image.startsWith("<svg") && image.contains("not settled"));
    QCOMPARE(image.count("<title>delay "), 2);
    // No temporary file left beside them.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);
}

//! The PNG is the SVG drawn at twice its size, on a machine without a display (a lab server
//! over ssh): its signature, and its IHDR's width and height against the SVG's.
void TestHatpicctlTeleopMap::pngWithoutADisplay()
{
#ifndef HATPICCTL_DRAWS_PNG
    // A build without the UI refuses --png before the map runs, and says what to do instead.
    const Run refused = runCtl({u"teleop-map"_s, u"--png"_s, u"map.png"_s});
    QCOMPARE(refused.code, 4);
    QVERIFY2(refused.err.contains("built without Qt's GUI and SVG libraries") &&
                 refused.err.contains("write --svg"),
             refused.err.constData());
    QVERIFY(refused.out.isEmpty());
    QSKIP("this hatpicctl is built without the UI: no PNG to check");
#endif
    QTemporaryDir dir;
    const QString png = dir.filePath(u"map.png"_s), svg = dir.filePath(u"map.svg"_s);
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const QString &name : {u"DISPLAY"_s, u"WAYLAND_DISPLAY"_s, u"QT_QPA_PLATFORM"_s})
        environment.remove(name);
    const Run run = runCtl({u"teleop-map"_s, u"--delays"_s, u"0,0.15"_s, u"--pc"_s, u"0,0.7"_s,
                            u"--duration"_s, u"6"_s, u"--svg"_s, svg, u"--png"_s, png},
                           kProcessTimeoutMs, environment);
    QVERIFY2(run.code == 0, run.err.constData());
    QFile chart(svg), image(png);
    QVERIFY(chart.open(QIODevice::ReadOnly) && image.open(QIODevice::ReadOnly));
    const QByteArray svgText = chart.readAll(), bytes = image.readAll();
    const auto attribute = [&](const char *name) {
        const QByteArray key = QByteArray(name) + "=\"";
        const qsizetype at = svgText.indexOf(key) + key.size();
        return qRound(svgText.mid(at, svgText.indexOf('"', at) - at).toDouble());
    };
    const auto bigEndian = [&](int at) {
        return int(quint8(bytes[at])) << 24 | int(quint8(bytes[at + 1])) << 16 |
               int(quint8(bytes[at + 2])) << 8 | int(quint8(bytes[at + 3]));
    };
    QVERIFY(bytes.startsWith("\x89PNG\r\n\x1a\n"));
    QCOMPARE(bytes.mid(12, 4), QByteArray("IHDR"));
    QVERIFY(attribute("width") > 300);
    QCOMPARE(bigEndian(16), 2 * attribute("width"));
    QCOMPARE(bigEndian(20), 2 * attribute("height"));
    QVERIFY(bytes.size() > 5000); // text and cells drawn, not an empty frame
}

void TestHatpicctlTeleopMap::variesAField()
{
    const Run run = runCtl({u"teleop-map"_s, u"--delays"_s, u"0.12:0.15/2"_s, u"--vary"_s,
                            u"M_adm=0.01,0.04"_s, u"--duration"_s, u"12"_s});
    QVERIFY2(run.code == 0, run.err.constData());
    const QList<QByteArray> lines = run.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 5);
    QVERIFY(lines[0].contains("M_adm"));
    // Four times the damping settles 120 and 150 ms (docs/teleop.md § Measured).
    QVERIFY2(lines[3].simplified().split(' ').at(4) == "1", lines[3].constData());
    QVERIFY2(lines[4].simplified().split(' ').at(4) == "1", lines[4].constData());
    QVERIFY2(lines[1].simplified().split(' ').at(3) == "0.0100", lines[1].constData());
}

void TestHatpicctlTeleopMap::controllerOffAndOn()
{
    const Run run = runCtl({u"teleop-map"_s, u"--delays"_s, u"0.3"_s, u"--pc"_s, u"0,0.5"_s});
    QVERIFY2(run.code == 0, run.err.constData());
    const QList<QByteArray> lines = run.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    const QList<QByteArray> off = lines[1].simplified().split(' ');
    const QList<QByteArray> on = lines[2].simplified().split(' ');
    QCOMPARE(off.at(2), QByteArray("0.000"));
    QCOMPARE(off.at(3), QByteArray("0")); // swings for good at 300 ms
    QCOMPARE(on.at(2), QByteArray("0.500"));
    QCOMPARE(on.at(3), QByteArray("1"));                         // the controller holds the contact
    QVERIFY(on.at(6).toDouble() > 0 && on.at(7).toDouble() > 0); // and its price shows
    QVERIFY(off.at(6).toDouble() == 0 && off.at(7).toDouble() == 0);
}

// Issue 35: --hand takes a list of torques (a sweep axis like --gains) and --contacts N pushes
// N times; a row per cell and contact, with the hand and contact columns.
void TestHatpicctlTeleopMap::handsAndContacts()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"map.csv"_s);
    const Run run = runCtl({u"teleop-map"_s, u"--delays"_s, u"0"_s, u"--hand"_s, u"0.03,0.05"_s,
                            u"--contacts"_s, u"2"_s, u"--duration"_s, u"4"_s, u"--csv"_s, csv});
    QVERIFY2(run.code == 0, run.err.constData());
    const QList<QByteArray> lines = run.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 1 + 2 * 2);
    QVERIFY(lines[0].contains(" hand ") && lines[0].contains(" contact ") &&
            lines[0].contains("damped_rest"));
    QVERIFY2(lines[1].simplified().startsWith("0.000 0.0200 0.0300 0.700 1 1 "),
             lines[1].constData());
    QVERIFY2(lines[4].simplified().startsWith("0.000 0.0200 0.0500 0.700 2 1 "),
             lines[4].constData());
    QVERIFY(run.err.contains("2 cells of 4 s"));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = file.readAll().trimmed().split('\n');
    QCOMPARE(rows.size(), 5);
    QVERIFY(rows[0].contains(",hand,contact,"));
    QVERIFY2(rows[3].contains(",0.05,1,"), rows[3].constData());
    // A hand SPEC still runs one hand of hatpic-sim's kinds.
    const Run spec = runCtl({u"teleop-map"_s, u"--delays"_s, u"0"_s, u"--hand"_s,
                             u"step:0.05:0:0.5"_s, u"--duration"_s, u"4"_s});
    QVERIFY2(spec.code == 0, spec.err.constData());
    QVERIFY(!spec.out.contains(" hand "));
}

void TestHatpicctlTeleopMap::badOptions_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("delay word") << QStringList{u"--delays"_s, u"0,soon"_s}
                                << QByteArray("--delays needs a number, got 'soon'.");
    QTest::newRow("delay range") << QStringList{u"--delays"_s, u"0,20"_s}
                                 << QByteArray("delay: must be from 0 to 10 s, got 20.");
    QTest::newRow("step") << QStringList{u"--gains"_s, u"0:1:0"_s}
                          << QByteArray("--gains needs a STEP above 0");
    QTest::newRow("field") << QStringList{u"--vary"_s, u"speed=1"_s}
                           << QByteArray("no tuning field 'speed'");
    QTest::newRow("field value") << QStringList{u"--vary"_s, u"M_adm=-1"_s}
                                 << QByteArray("M_adm: must be > 0, got -1.");
    QTest::newRow("threads") << QStringList{u"--threads"_s, u"0"_s}
                             << QByteArray("--threads needs a whole number from 1 to 64, got '0'");
    QTest::newRow("loss") << QStringList{u"--loss"_s, u"2"_s}
                          << QByteArray("loss: must be from 0 to 1, got 2.");
    QTest::newRow("pc and vary") << QStringList{u"--pc"_s, u"0"_s, u"--vary"_s, u"M_adm=0.1"_s}
                                 << QByteArray("give one of them");
    QTest::newRow("pc value") << QStringList{u"--pc"_s, u"2"_s}
                              << QByteArray("pc_damping_max: must be");
    QTest::newRow("hand") << QStringList{u"--hand"_s, u"push"_s} << QByteArray("--hand");
    QTest::newRow("hand list") << QStringList{u"--hand"_s, u"0.05,x"_s}
                               << QByteArray("--hand needs a number, got 'x'.");
    QTest::newRow("hand torque") << QStringList{u"--hand"_s, u"0.05,12"_s}
                                 << QByteArray("hand 12 N·m");
    QTest::newRow("contacts word") << QStringList{u"--contacts"_s, u"two"_s}
                                   << QByteArray("--contacts needs a whole number from 1 to 100");
    QTest::newRow("contacts range") << QStringList{u"--contacts"_s, u"0"_s}
                                    << QByteArray("contacts must be from 1 to 100, got 0.");
    QTest::newRow("contacts of a sine")
        << QStringList{u"--contacts"_s, u"2"_s, u"--hand"_s, u"sine:0.05:1"_s}
        << QByteArray("contacts above 1 need a constant hand");
    QTest::newRow("folder") << QStringList{u"--csv"_s, u"/nonexistent/m.csv"_s}
                            << QByteArray("the folder /nonexistent does not exist");
#ifdef HATPICCTL_DRAWS_PNG
    QTest::newRow("png folder") << QStringList{u"--png"_s, u"/nonexistent/m.png"_s}
                                << QByteArray("--png /nonexistent/m.png: the folder /nonexistent");
#endif
}

void TestHatpicctlTeleopMap::badOptions()
{
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, message);
    const Run run = runCtl(QStringList{u"teleop-map"_s} + arguments);
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.startsWith("hatpicctl: ") && run.err.contains(message), run.err.constData());
    QVERIFY(run.out.isEmpty()); // refused before anything ran
}

void TestHatpicctlTeleopMap::keepsAnExistingFile()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"map.csv"_s);
    QFile file(csv);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("mine\n");
    file.close();
    Run run =
        runCtl({u"teleop-map"_s, u"--delays"_s, u"0"_s, u"--duration"_s, u"3"_s, u"--csv"_s, csv});
    QCOMPARE(run.code, 4);
    QVERIFY(run.err.contains("exists; add --force"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("mine\n"));
    file.close();
    run = runCtl({u"teleop-map"_s, u"--delays"_s, u"0"_s, u"--duration"_s, u"3"_s, u"--csv"_s, csv,
                  u"--force"_s});
    QCOMPARE(run.code, 0);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().startsWith("delay,gain,pc,"));
}

QTEST_GUILESS_MAIN(TestHatpicctlTeleopMap)
#include "tst_hatpicctlteleopmap.moc"
