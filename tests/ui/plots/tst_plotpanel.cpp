// PlotPanel: samples reach the graphs, repaint only on change, pause, units, legends, cursor,
// bands, events and exports.
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"

#include <QFontMetrics>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>

#include <cmath>
#include <numbers>

using namespace hatpic;

using namespace Qt::StringLiterals;

namespace {

void fill(SampleBuffer &buffer, double from, double to, double rateHz = 1000)
{
    const int n = int(std::lround((to - from) * rateHz));
    for (int i = 0; i < n; ++i) {
        Sample s;
        s.t_s = from + i / rateHz;
        s.theta = 0.3 * std::sin(2 * std::numbers::pi * 0.5 * s.t_s);
        s.tau = -0.1 * std::sin(s.t_s);
        s.tau_rec = -0.4 * s.theta;
        s.tau_total = s.tau_rec;
        s.v_ref = 0.5 * s.theta;
        s.p_ref = s.t_s * 0.01;
        buffer.append(s);
    }
}

QPoint legendItemCenter(PlotPanel &panel, PlotPanel::Plot plot, Channel channel)
{
    QCPLegend *legend = panel.legend(plot);
    QCPAbstractLegendItem *item = legend->itemWithPlottable(panel.graph(channel));
    return item ? item->rect().center() : QPoint();
}

} // namespace

class TestPlotPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void drawsSamplesAndFollowsLatest();
    void decimatesLongWindow();
    void repaintsOnlyWhenSomethingChanged();
    void pauseFreezesViewWhileSourceFills();
    void windowLength_data();
    void windowLength();
    void degreesConvertOnlyForDisplay();
    void legendClickTogglesSeries();
    void cursorReadsValuesAtTime();
    void mouseMoveSetsCursor();
    void bandsFollowDeviceParams();
    void eventsAreMarked();
    void oneColourPerQuantity();
    void tauExtSeenOnTauRec();
    void shortPlotsStayReadable();
    void legendsFitShortPlots();
    void eventLabelAtTheRightEdgeStaysReadable();
    void autoscaleFitsAndFixedStays();
    void exportsImage_data();
    void exportsImage();
    void exportsVisibleCsv();

private:
    PlotPanel *m_panel = nullptr;
    SampleBuffer *m_buffer = nullptr;
};

void TestPlotPanel::init()
{
    m_buffer = new SampleBuffer;
    m_panel = new PlotPanel;
    m_panel->resize(1000, 700);
    m_panel->setSource(m_buffer);
    m_panel->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel));
}

void TestPlotPanel::cleanup()
{
    delete m_panel;
    delete m_buffer;
}

void TestPlotPanel::drawsSamplesAndFollowsLatest()
{
    QCOMPARE(m_panel->pointCount(Channel::Theta), 0);
    fill(*m_buffer, 0, 3);
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->pointCount(Channel::Theta) > 0, 5000); // the timer did it
    // Less data than the window: the window starts at the first sample.
    QCOMPARE(m_panel->viewStart(), m_buffer->firstTime());
    QCOMPARE(m_panel->viewEnd() - m_panel->viewStart(), m_panel->windowLength());
    // More: it ends at the newest sample.
    fill(*m_buffer, 3, 15);
    m_panel->repaintIfNeeded();
    QCOMPARE(m_panel->viewEnd(), m_buffer->lastTime());
    QCOMPARE(m_panel->viewEnd() - m_panel->viewStart(), m_panel->windowLength());
    QVERIFY(m_panel->pointCount(Channel::TauRec) > 0);
    QVERIFY(m_panel->pointCount(Channel::PRef) > 0);
    QCOMPARE(m_panel->pointCount(Channel::Omega), 0); // hidden by default
    const QCPGraphData last = *(m_panel->graph(Channel::Theta)->data()->constEnd() - 1);
    QCOMPARE(last.key, m_buffer->lastTime());
}

void TestPlotPanel::decimatesLongWindow()
{
    m_panel->setWindowLength(60);
    fill(*m_buffer, 0, 60);
    m_panel->repaintNow(); // lays the plots out at this size
    m_panel->repaintNow();
    const int width = m_panel->axisRect(PlotPanel::Plot::Angle)->width();
    QVERIFY(width > 100);
    QVERIFY2(m_panel->pointCount(Channel::Theta) <= 2 * width + 4,
             qPrintable(QString::number(m_panel->pointCount(Channel::Theta))));
    QVERIFY(m_panel->pointCount(Channel::Theta) > width / 2);
}

void TestPlotPanel::repaintsOnlyWhenSomethingChanged()
{
    fill(*m_buffer, 0, 1);
    m_panel->repaintIfNeeded();
    const quint64 before = m_panel->repaintStats().replots;
    m_panel->repaintIfNeeded();
    m_panel->repaintIfNeeded();
    QCOMPARE(m_panel->repaintStats().replots, before);
    fill(*m_buffer, 1, 1.01);
    m_panel->repaintIfNeeded();
    QCOMPARE(m_panel->repaintStats().replots, before + 1);
}

void TestPlotPanel::pauseFreezesViewWhileSourceFills()
{
    QSignalSpy paused(m_panel, &PlotPanel::pausedChanged);
    m_panel->setWindowLength(1);
    fill(*m_buffer, 0, 2);
    m_panel->repaintNow();
    const double end = m_panel->viewEnd();
    m_panel->setPaused(true);
    QCOMPARE(paused.size(), 1);
    fill(*m_buffer, 2, 4); // the link keeps delivering
    m_panel->repaintNow();
    QCOMPARE(m_panel->viewEnd(), end);
    QCOMPARE(m_buffer->lastTime(), 4 - 0.001);
    const QCPGraphData last = *(m_panel->graph(Channel::Theta)->data()->constEnd() - 1);
    QVERIFY(last.key <= end);
    m_panel->setPaused(false);
    m_panel->repaintNow();
    QCOMPARE(m_panel->viewEnd(), m_buffer->lastTime());
}

void TestPlotPanel::windowLength_data()
{
    QTest::addColumn<double>("seconds");
    QTest::newRow("5 s") << 5.0;
    QTest::newRow("10 s") << 10.0;
    QTest::newRow("30 s") << 30.0;
    QTest::newRow("60 s") << 60.0;
}

void TestPlotPanel::windowLength()
{
    QFETCH(double, seconds);
    fill(*m_buffer, 0, 70, 200);
    m_panel->setWindowLength(seconds);
    m_panel->repaintNow();
    QCOMPARE(m_panel->viewEnd() - m_panel->viewStart(), seconds);
    const QCPGraphData first = *m_panel->graph(Channel::Theta)->data()->constBegin();
    QVERIFY(first.key >= m_panel->viewStart() - 0.01); // at most one neighbour before
}

void TestPlotPanel::degreesConvertOnlyForDisplay()
{
    fill(*m_buffer, 0, 1);
    m_panel->repaintNow();
    const double radians = (m_panel->graph(Channel::Theta)->data()->constEnd() - 1)->value;
    QVERIFY(m_panel->axisRect(PlotPanel::Plot::Angle)
                ->axis(QCPAxis::atLeft)
                ->label()
                .contains(QStringLiteral("rad")));
    m_panel->setAngleInDegrees(true);
    m_panel->repaintNow();
    const double degrees = (m_panel->graph(Channel::Theta)->data()->constEnd() - 1)->value;
    QCOMPARE(degrees, radians * 180 / std::numbers::pi);
    QVERIFY(m_panel->axisRect(PlotPanel::Plot::Angle)
                ->axis(QCPAxis::atLeft)
                ->label()
                .contains(QStringLiteral("°")));
    QCOMPARE(m_buffer->value(Channel::Theta, m_buffer->size() - 1), radians); // data stay SI
    // Torques are not angles.
    QVERIFY(m_panel->readout().contains(QStringLiteral("N·m")));

    // ω, when shown, has its own axis with numbers on it, in degrees too.
    m_panel->setChannelVisible(Channel::Omega, true);
    m_panel->repaintNow();
    QCPAxis *omega = m_panel->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atRight);
    QVERIFY(omega->visible());
    QVERIFY(omega->label().contains(QStringLiteral("°/s")));
    QVERIFY(omega->tickLabels());
    QVERIFY(!omega->tickVectorLabels().isEmpty());
}

void TestPlotPanel::legendClickTogglesSeries()
{
    fill(*m_buffer, 0, 1);
    m_panel->repaintNow();
    QSignalSpy spy(m_panel, &PlotPanel::channelVisibilityChanged);
    const QPoint center = legendItemCenter(*m_panel, PlotPanel::Plot::Torque, Channel::TauExt);
    QVERIFY(!center.isNull());
    QTest::mouseClick(m_panel->customPlot(), Qt::LeftButton, {}, center);
    QCOMPARE(spy.size(), 1);
    QCOMPARE(spy.at(0).at(0).value<Channel>(), Channel::TauExt);
    QCOMPARE(spy.at(0).at(1).toBool(), false);
    QVERIFY(!m_panel->isChannelVisible(Channel::TauExt));
    m_panel->repaintNow();
    QCOMPARE(m_panel->pointCount(Channel::TauExt), 0);
    QTest::mouseClick(m_panel->customPlot(), Qt::LeftButton, {}, center);
    QVERIFY(m_panel->isChannelVisible(Channel::TauExt));
}

void TestPlotPanel::cursorReadsValuesAtTime()
{
    fill(*m_buffer, 0, 2);
    m_panel->repaintNow();
    const qsizetype index = 700;
    m_panel->setCursorTime(m_buffer->time(index) + 0.0002);
    const QString text = m_panel->readout();
    QVERIFY2(text.startsWith(QStringLiteral("t = 0.700 s")), qPrintable(text));
    const QString theta =
        QString::number(m_buffer->value(Channel::Theta, index), 'f', 4).replace(u'-', u'−');
    QVERIFY2(text.contains(QStringLiteral("θ = ") + theta), qPrintable(text));
    QVERIFY(m_panel->graph(Channel::Theta)->name().contains(theta));
    m_panel->setCursorTime(std::nullopt);
    QVERIFY(m_panel->readout().startsWith(QStringLiteral("t = 1.999 s")));
}

void TestPlotPanel::mouseMoveSetsCursor()
{
    fill(*m_buffer, 0, 12);
    m_panel->repaintNow();
    QCPAxisRect *rect = m_panel->axisRect(PlotPanel::Plot::Torque);
    const QPoint at = rect->rect().center();
    QTest::mouseMove(m_panel->customPlot(), at);
    QTRY_VERIFY(m_panel->cursorTime().has_value());
    const double expected = rect->axis(QCPAxis::atBottom)->pixelToCoord(at.x());
    QVERIFY(std::abs(*m_panel->cursorTime() - expected) < 0.05);
}

void TestPlotPanel::bandsFollowDeviceParams()
{
    DeviceParams params;
    params.theta0 = 0.05;
    params.Q_dz = 0.02;
    params.N = 0.1;
    m_panel->setDeviceParams(params);
    fill(*m_buffer, 0, 1);
    m_panel->repaintNow();
    // The angle axis keeps the notch band in view.
    const QCPRange range =
        m_panel->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atLeft)->range();
    QVERIFY(range.contains(params.theta0 + params.N));
    QVERIFY(range.contains(params.theta0 - params.N));
    QVERIFY(m_panel->bandsVisible());
    QSignalSpy spy(m_panel, &PlotPanel::bandsVisibilityChanged);
    m_panel->setBandsVisible(false);
    QCOMPARE(spy.size(), 1);
    m_panel->setDeviceParams(std::nullopt);
    m_panel->repaintNow();
}

void TestPlotPanel::oneColourPerQuantity()
{
    // θ and τ_rec once shared a blue.
    QSet<QRgb> colours;
    for (Channel channel : kAllChannels) {
        QCOMPARE(m_panel->graph(channel)->pen().color(), palette::channel(channel));
        if (isSampleChannel(channel))
            colours.insert(palette::channel(channel).rgb());
    }
    QCOMPARE(colours.size(), qsizetype(kSampleChannelCount));
    // τ_fx's parts are variants of τ_fx: its colour, each in a line style of its own.
    QSet<int> styles{int(m_panel->graph(Channel::TauFx)->pen().style())};
    for (Channel part : {Channel::TauDet, Channel::TauWall, Channel::TauVib}) {
        QCOMPARE(palette::channel(part), palette::channel(Channel::TauFx));
        styles.insert(int(m_panel->graph(part)->pen().style()));
    }
    QCOMPARE(styles.size(), 4);
    // τ_total = τ_rec while τ_ext = 0: τ_rec, drawn first, stays visible around and through
    // the dashed τ_total on top.
    const QPen rec = m_panel->graph(Channel::TauRec)->pen();
    const QPen total = m_panel->graph(Channel::TauTotal)->pen();
    QVERIFY(rec.widthF() > total.widthF() + 1);
    QCOMPARE(total.style(), Qt::DashLine);
    QCPLayer *layer = m_panel->graph(Channel::TauRec)->layer();
    QCOMPARE(m_panel->graph(Channel::TauTotal)->layer(), layer);
    QVERIFY(layer->children().indexOf(m_panel->graph(Channel::TauRec)) <
            layer->children().indexOf(m_panel->graph(Channel::TauTotal)));
}

// Issue 27: at the teleoperation demo's equilibrium τ_ext equals τ_rec, and its 1 px line
// vanished in τ_rec's 3 px one: the wall's push could not be seen. τ_ext is drawn on top,
// wide enough to be seen as its own colour, with τ_rec still showing on both sides of it.
void TestPlotPanel::tauExtSeenOnTauRec()
{
    for (int i = 0; i < 3000; ++i) {
        Sample s;
        s.t_s = i / 1000.0;
        s.tau_rec = -0.025;
        s.tau_ext = -0.025;
        s.tau_total = -0.05;
        s.tau = -0.05;
        m_buffer->append(s);
    }
    m_panel->setAutoscale(false);
    m_panel->axisRect(PlotPanel::Plot::Torque)->axis(QCPAxis::atLeft)->setRange(-0.1, 0.1);
    m_panel->repaintIfNeeded();
    QCustomPlot *plot = m_panel->customPlot();
    plot->replot();
    const QImage image = plot->grab().toImage();
    if (qEnvironmentVariableIsSet("HATPIC_DUMP"))
        image.save(QStringLiteral("/tmp/tauext.png"));
    QCPAxisRect *torque = m_panel->axisRect(PlotPanel::Plot::Torque);
    QCPLayer *layer = m_panel->graph(Channel::TauRec)->layer();
    QVERIFY(layer->children().indexOf(m_panel->graph(Channel::TauRec)) <
            layer->children().indexOf(m_panel->graph(Channel::TauExt)));
    const auto near = [](QRgb pixel, const QColor &colour) {
        const QColor c(pixel);
        return std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                   std::abs(c.blue() - colour.blue()) <
               60;
    };
    const int y = int(std::lround(torque->axis(QCPAxis::atLeft)->coordToPixel(-0.025)));
    int columns = 0;
    const int dataEnd = int(torque->axis(QCPAxis::atBottom)->coordToPixel(2.9));
    for (int x = torque->left() + 20; x < std::min(dataEnd, torque->right() - 20); x += 17) {
        int ext = 0, rec = 0;
        for (int dy = -6; dy <= 6; ++dy) {
            const QRgb pixel = image.pixel(x, y + dy);
            ext += near(pixel, palette::channel(Channel::TauExt));
            rec += near(pixel, palette::channel(Channel::TauRec));
        }
        QVERIFY2(ext >= 2, qPrintable(QStringLiteral("x %1: τ_ext %2 px").arg(x).arg(ext)));
        QVERIFY2(rec >= 2, qPrintable(QStringLiteral("x %1: τ_rec %2 px").arg(x).arg(rec)));
        ++columns;
    }
    QVERIFY(columns > 5);
}

// Issue 27: at 1280×720 a bottom panel squeezed the plots until their tick labels printed over
// each other. However short the panel is asked to be, each y axis has its labels apart.
void TestPlotPanel::shortPlotsStayReadable()
{
    fill(*m_buffer, 0, 3);
    m_panel->resize(1000, 200); // less than the plots need: the minimum holds
    QCustomPlot *plot = m_panel->customPlot();
    for (int i = 0; i < 3; ++i) {
        m_panel->repaintIfNeeded();
        plot->replot();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    }
    QVERIFY(plot->height() >= PlotPanel::kMinPlotsHeight);
    const int label = QFontMetrics(plot->xAxis->tickLabelFont()).height();
    for (PlotPanel::Plot kind :
         {PlotPanel::Plot::Angle, PlotPanel::Plot::Torque, PlotPanel::Plot::Reference}) {
        QCPAxis *y = m_panel->axisRect(kind)->axis(QCPAxis::atLeft);
        const QVector<double> ticks = y->tickVector();
        QVERIFY2(!ticks.isEmpty(), qPrintable(QString::number(int(kind))));
        for (qsizetype i = 1; i < ticks.size(); ++i) {
            const double apart =
                std::abs(y->coordToPixel(ticks[i]) - y->coordToPixel(ticks[i - 1]));
            QVERIFY2(apart >= label,
                     qPrintable(QStringLiteral("plot %1: ticks %2 px apart, labels %3 px")
                                    .arg(int(kind))
                                    .arg(apart)
                                    .arg(label)));
        }
    }
}

void TestPlotPanel::eventsAreMarked()
{
    const int before = m_panel->customPlot()->itemCount();
    m_panel->setEvents(
        {{0.5, QStringLiteral("K_max 0.4 → 0.6")}, {1.5, QStringLiteral("N 0.1 → 0.2")}});
    const int perEvent = PlotPanel::kPlotCount + 1; // a line per plot and a label
    QCOMPARE(m_panel->customPlot()->itemCount(), before + 2 * perEvent);
    m_panel->addEvent({2.0, QStringLiteral("push")});
    QCOMPARE(m_panel->customPlot()->itemCount(), before + 3 * perEvent);
    QCOMPARE(m_panel->events().size(), 3);
    m_panel->setEvents({});
    QCOMPARE(m_panel->customPlot()->itemCount(), before);
}

void TestPlotPanel::legendsFitShortPlots()
{
    // Issue 27: at the plots' minimum height the legends were squeezed until their entries
    // clipped ("τ_rec" read "τ rec"). Every entry whole and inside its plot's row, at the
    // minimum and when one more series is shown there; all entries back at a roomy height.
    fill(*m_buffer, 0, 3);
    QCustomPlot *plot = m_panel->customPlot();
    auto layOut = [&] {
        for (int i = 0; i < 3; ++i) {
            m_panel->repaintNow();
            QCoreApplication::processEvents(); // the queued replot of a changed layout
        }
    };
    auto checkFits = [&](const QString &when) {
        for (PlotPanel::Plot kind :
             {PlotPanel::Plot::Angle, PlotPanel::Plot::Torque, PlotPanel::Plot::Reference}) {
            QCPLegend *legend = m_panel->legend(kind);
            const QRect row = m_panel->axisRect(kind)->outerRect();
            const QString where = u"%1, plot %2"_s.arg(when).arg(int(kind));
            QVERIFY2(legend->itemCount() > 0, qPrintable(where));
            for (int k = 0; k < legend->itemCount(); ++k) {
                QCPAbstractLegendItem *item = legend->item(k);
                const QRect r = item->outerRect();
                const int needs = item->minimumOuterSizeHint().height();
                QVERIFY2(r.height() >= needs, qPrintable(u"%1, entry %2: %3 px of %4"_s.arg(where)
                                                             .arg(k)
                                                             .arg(r.height())
                                                             .arg(needs)));
                QVERIFY2(r.top() >= row.top() && r.bottom() <= row.bottom(),
                         qPrintable(u"%1, entry %2: rows %3–%4 outside %5–%6"_s.arg(where)
                                        .arg(k)
                                        .arg(r.top())
                                        .arg(r.bottom())
                                        .arg(row.top())
                                        .arg(row.bottom())));
            }
        }
    };
    auto listed = [&](PlotPanel::Plot kind, Channel channel) {
        return m_panel->legend(kind)->hasItemWithPlottable(m_panel->graph(channel));
    };

    m_panel->resize(1000, 200); // the minimum holds
    layOut();
    QCOMPARE(plot->height(), PlotPanel::kMinPlotsHeight);
    checkFits(u"minimum"_s);
    // What is shown stays listed; what is hidden makes room.
    for (Channel channel : {Channel::TauRec, Channel::TauExt, Channel::TauTotal, Channel::Tau})
        QVERIFY(listed(PlotPanel::Plot::Torque, channel));
    QVERIFY(listed(PlotPanel::Plot::Angle, Channel::Theta));
    QVERIFY(!listed(PlotPanel::Plot::Torque, Channel::TauDet));

    m_panel->setChannelVisible(Channel::TauDet, true);
    m_panel->setChannelVisible(Channel::Omega, true);
    layOut();
    QVERIFY(listed(PlotPanel::Plot::Torque, Channel::TauDet));
    QVERIFY(listed(PlotPanel::Plot::Angle, Channel::Omega));
    checkFits(u"minimum, τ_det and ω shown"_s);

    m_panel->setChannelVisible(Channel::TauDet, false);
    m_panel->resize(1000, 700);
    layOut();
    checkFits(u"roomy"_s);
    QVERIFY(listed(PlotPanel::Plot::Torque, Channel::TauDet)); // greyed, clickable again
}

void TestPlotPanel::eventLabelAtTheRightEdgeStaysReadable()
{
    // A live push is marked at the newest sample, i.e. at the right edge of the view: its label
    // must turn to the left of the line instead of being cut off by the plot's edge.
    fill(*m_buffer, 0, 15);
    m_panel->repaintNow();
    m_panel->repaintNow(); // laid out at this size
    // Labels are short (the names); the changes show on hover.
    const QString late = QStringLiteral("K_max, N");
    const QString early = QStringLiteral("K_max");
    m_panel->setEvents({{m_panel->viewStart() + 1, QStringLiteral("K_max 0.4 → 0.3")},
                        {m_buffer->lastTime(), QStringLiteral("K_max 0.3 → 0.6; N 0.1 → 0.12")}});
    m_panel->repaintNow();
    QCPAxisRect *angle = m_panel->axisRect(PlotPanel::Plot::Angle);
    QCPAxis *x = angle->axis(QCPAxis::atBottom);
    int checked = 0;
    for (int i = 0; i < m_panel->customPlot()->itemCount(); ++i) {
        auto *label = qobject_cast<QCPItemText *>(m_panel->customPlot()->item(i));
        if (!label || (label->text() != late && label->text() != early))
            continue;
        const double line = x->coordToPixel(label->position->coords().x());
        const double left = label->topLeft->pixelPosition().x();
        const double right = label->topRight->pixelPosition().x();
        QVERIFY2(left >= angle->left() - 1 && right <= angle->right() + 1,
                 qPrintable(QStringLiteral("%1: %2…%3 outside %4…%5")
                                .arg(label->text())
                                .arg(left)
                                .arg(right)
                                .arg(angle->left())
                                .arg(angle->right())));
        // Beside its line, not somewhere else.
        QVERIFY(std::abs(left - line) <= 1 || std::abs(right - line) <= 1);
        ++checked;
    }
    QCOMPARE(checked, 2);

    // Hovering a marker's line shows what it stands for.
    const QPoint at(int(x->coordToPixel(m_buffer->lastTime())), int(angle->center().y()));
    QTest::mouseMove(m_panel->customPlot(), at);
    QTRY_VERIFY2(QToolTip::text().contains(QStringLiteral("N 0.1 → 0.12")),
                 qPrintable(QToolTip::text()));
}

void TestPlotPanel::autoscaleFitsAndFixedStays()
{
    fill(*m_buffer, 0, 2);
    m_panel->repaintNow();
    QCPAxis *torque = m_panel->axisRect(PlotPanel::Plot::Torque)->axis(QCPAxis::atLeft);
    for (qsizetype i = m_buffer->lowerBound(m_panel->viewStart()); i < m_buffer->size(); ++i)
        QVERIFY(torque->range().contains(m_buffer->value(Channel::TauRec, i)));
    QSignalSpy spy(m_panel, &PlotPanel::autoscaleChanged);
    m_panel->setAutoscale(false);
    QCOMPARE(spy.size(), 1);
    const QCPRange fixed = torque->range();
    Sample big;
    big.t_s = 2.5;
    big.tau_rec = 5.0;
    m_buffer->append(big);
    m_panel->repaintNow();
    QCOMPARE(torque->range(), fixed);
    m_panel->setAutoscale(true);
    m_panel->repaintNow();
    QVERIFY(torque->range().contains(5.0));
}

void TestPlotPanel::exportsImage_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("magic");
    QTest::newRow("png") << QStringLiteral("view.png") << QByteArray("\x89PNG");
    QTest::newRow("pdf") << QStringLiteral("view.pdf") << QByteArray("%PDF");
}

void TestPlotPanel::exportsImage()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, magic);
    QTemporaryDir dir;
    fill(*m_buffer, 0, 2);
    const QString path = dir.filePath(name);
    QString error;
    QVERIFY2(m_panel->exportImage(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.read(magic.size()) == magic);
    QVERIFY(file.size() > 1000);
}

void TestPlotPanel::exportsVisibleCsv()
{
    QTemporaryDir dir;
    fill(*m_buffer, 0, 20);
    m_panel->setWindowLength(5);
    m_panel->repaintNow();
    const QString path = dir.filePath(QStringLiteral("view.csv"));
    QString error;
    const qsizetype rows = m_panel->exportCsv(path, &error);
    QVERIFY2(rows > 0, qPrintable(error));
    const qsizetype expected =
        m_buffer->upperBound(m_panel->viewEnd()) - m_buffer->lowerBound(m_panel->viewStart());
    QCOMPARE(rows, expected);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(
        lines.first(),
        QByteArray("t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,tau_pc,"
                   "pc_reserve,event"));
    QCOMPARE(lines.size(), rows + 2); // header, rows, empty after the last newline
    const QList<QByteArray> firstRow = lines.at(1).split(',');
    QCOMPARE(firstRow.size(), 14);
    QVERIFY(firstRow.at(0).toDouble() >= m_panel->viewStart());
}

QTEST_MAIN(TestPlotPanel)
#include "tst_plotpanel.moc"
