// KnobsView: a board's knobs and tilt, drawn from the newest sample (real widget, offscreen).
#include "plots/knobsview.h"
#include "plots/palette.h"

#include <QImage>
#include <QTest>

#include <cmath>
#include <memory>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

Sample boardSample(double theta1, double theta2, double roll, double pitch)
{
    Sample s;
    s.theta = theta1;
    auto board = std::make_shared<BoardSample>();
    board->axes = 4;
    board->more[0].theta = theta2;
    board->roll = roll;
    board->pitch = pitch;
    s.board = std::move(board);
    return s;
}

//! Pixels of `colour` (give or take antialiasing) inside `area` of `image`.
int pixelsOf(const QImage &image, const QRect &area, const QColor &colour)
{
    int n = 0;
    for (int y = area.top(); y <= area.bottom(); ++y) {
        for (int x = area.left(); x <= area.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                     std::abs(c.blue() - colour.blue()) <
                 40;
        }
    }
    return n;
}

} // namespace

class TestKnobsView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void nothingBeforeASample()
    {
        KnobsView view;
        QCOMPARE(view.knobs(), 0);
        QVERIFY(!view.showsTilt());
        QCOMPARE(view.text(), u"No samples"_s);
        QVERIFY(std::isnan(view.knobAngle(1)));
    }

    void oneKnobWithoutTilt()
    {
        KnobsView view;
        Sample s;
        s.theta = 0.5;
        view.showSamples({s});
        QCOMPARE(view.knobs(), 1);
        QVERIFY(!view.showsTilt());
        QVERIFY(std::isnan(view.knobAngle(2)));
        QVERIFY2(view.text().startsWith(u"Knob 1: "_s) && !view.text().contains(u"roll"_s),
                 qPrintable(view.text()));
    }

    void theNewestSampleOfABoard()
    {
        KnobsView view;
        view.showSamples({boardSample(0.1, 0.2, 0, 0), boardSample(0.3, -0.4, 0.25, -0.5)});
        QCOMPARE(view.knobs(), 4);
        QVERIFY(view.showsTilt());
        QCOMPARE(view.knobAngle(1), 0.3);
        QCOMPARE(view.knobAngle(2), -0.4);
        QCOMPARE(view.knobAngle(3), 0.0);
        QVERIFY(std::isnan(view.knobAngle(5)));
        const QString rad = view.text();
        QVERIFY2(rad.contains(u"Knob 4: "_s) && rad.contains(u"; roll "_s), qPrintable(rad));
        view.setUnits(DisplayUnits(true, ReferenceMode::Translation));
        QVERIFY2(view.text().contains(u"°"_s) && view.text() != rad, qPrintable(view.text()));
        QVERIFY(view.sizeHint().width() > 5 * 84);
        view.showSamples({}); // an empty batch keeps what is drawn
        QCOMPARE(view.knobs(), 4);
        view.clear();
        QCOMPARE(view.knobs(), 0);
    }

    void pointersShowTheAngles()
    {
        // Knob 1 at 0 points up, knob 2 at π/2 points right (clockwise as θ grows).
        KnobsView view;
        view.showSamples({boardSample(0, std::numbers::pi / 2, 0, 0)});
        view.resize(view.sizeHint());
        const QImage image = view.grab().toImage();
        const QColor pointer = palette::channel(Channel::Theta);
        const int dial = 84;
        const int gap = 16;
        const QRect knob1(gap, gap, dial, dial);
        const QRect knob2(gap + dial + gap, gap, dial, dial);
        const QPoint c1 = knob1.center();
        const QPoint c2 = knob2.center();
        // Above knob 1's centre, not to its right; to knob 2's right, not above it.
        QVERIFY(pixelsOf(image, QRect(c1.x() - 3, knob1.top() + 8, 7, dial / 3), pointer) > 10);
        QCOMPARE(pixelsOf(image, QRect(c1.x() + 8, c1.y() - 3, dial / 3, 7), pointer), 0);
        QVERIFY(pixelsOf(image, QRect(c2.x() + 8, c2.y() - 3, dial / 3, 7), pointer) > 10);
        QCOMPARE(pixelsOf(image, QRect(c2.x() - 3, knob2.top() + 8, 7, dial / 3), pointer), 0);
    }
};

QTEST_MAIN(TestKnobsView)
#include "tst_knobsview.moc"
