// The light/dark theme on the real MainWindow (offscreen): View → Theme switches the widgets'
// palette and the plots' background, axes and legends with it; every visible text-bearing
// widget stays readable (its text against its background on a grab, at least 3:1) in both;
// the data colours read on both plot backgrounds; the choice is saved and restored.
#include "editor/derivedfiguresview.h"
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/plottheme.h"
#include "plots/qcp.h"
#include "window/mainwindow.h"
#include "window/theme.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>

#include <cmath>

using namespace hatpic;

namespace {

double luminance(QRgb rgb)
{
    auto lin = [](int c) {
        const double v = c / 255.0;
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * lin(qRed(rgb)) + 0.7152 * lin(qGreen(rgb)) + 0.0722 * lin(qBlue(rgb));
}

double contrast(double a, double b)
{
    return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05);
}

//! The most common pixel (a widget's background).
QRgb mostCommon(const QImage &image, QHash<QRgb, int> *counted = nullptr)
{
    QHash<QRgb, int> counts;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x)
            ++counts[image.pixel(x, y) | 0xff000000];
    }
    QRgb background = 0;
    int most = -1;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it) {
        if (it.value() > most) {
            most = it.value();
            background = it.key();
        }
    }
    if (counted)
        *counted = counts;
    return background;
}

//! Contrast of the most contrasting pixel against the most common one (the background).
double textContrast(const QImage &image)
{
    QHash<QRgb, int> counts;
    const double lb = luminance(mostCommon(image, &counts));
    double best = 1;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        best = std::max(best, contrast(lb, luminance(it.key())));
    return best;
}

//! Shows `window` at 1280×720 in the theme `choice`; its theme controller, or null.
ThemeController *showIn(MainWindow &window, int choice)
{
    window.resize(1280, 720);
    window.show();
    auto *theme = window.findChild<ThemeController *>(QStringLiteral("themeController"));
    if (!QTest::qWaitForWindowExposed(&window) || !theme)
        return nullptr;
    theme->setChoice(static_cast<ThemeController::Choice>(choice));
    return theme;
}

QString textOf(const QWidget *w)
{
    if (const auto *label = qobject_cast<const QLabel *>(w))
        return label->pixmap().isNull() ? label->text() : QString();
    if (const auto *button = qobject_cast<const QAbstractButton *>(w)) {
        if (const auto *tool = qobject_cast<const QToolButton *>(w);
            tool && tool->toolButtonStyle() == Qt::ToolButtonIconOnly && !tool->icon().isNull())
            return {};
        return button->text();
    }
    return {};
}

} // namespace

class TestTheme : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void switchingChangesThePlots();
    void widgetsStayReadable_data();
    void widgetsStayReadable();
    void dataColoursReadOnBoth();
    void derivedFiguresFollowTheTheme_data();
    void derivedFiguresFollowTheTheme();
    void choiceIsSaved();
};

void TestTheme::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("hatpic-test"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_theme"));
    QSettings().clear();
}

void TestTheme::cleanup()
{
    QSettings().clear();
}

void TestTheme::switchingChangesThePlots()
{
    MainWindow window;
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto *theme = window.findChild<ThemeController *>(QStringLiteral("themeController"));
    QVERIFY(theme);
    QCOMPARE(theme->choice(), ThemeController::Choice::System);
    // View → Theme.
    QMenu *view = nullptr;
    for (QAction *a : window.menuBar()->actions()) {
        if (a->menu() && a->menu()->objectName().isEmpty() &&
            a->text().remove(u'&') == QStringLiteral("View"))
            view = a->menu();
    }
    QVERIFY(view);
    QVERIFY(view->actions().contains(theme->menu()->menuAction()));
    QCOMPARE(theme->menu()->actions().size(), 3);
    const QColor systemWindow = QApplication::palette().color(QPalette::Window);
    QCustomPlot *plot = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"))->customPlot();

    auto background = [plot] {
        QApplication::processEvents();
        plot->replot();
        return QColor(plot->grab().toImage().pixel(3, 3)).lightness();
    };
    window.findChild<QAction *>(QStringLiteral("theme_dark"))->trigger();
    QVERIFY(theme->isDark());
    QVERIFY(plottheme::isDark(QApplication::palette()));
    QVERIFY2(background() < 60, "the plots' background follows the dark theme");
    QCPAxis *y =
        window.findChild<PlotPanel *>()->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atLeft);
    QCOMPARE(y->tickLabelColor(), QApplication::palette().color(QPalette::Text));
    QCOMPARE(window.findChild<PlotPanel *>()->legend(PlotPanel::Plot::Angle)->textColor(),
             QApplication::palette().color(QPalette::Text));

    // Issue 27: the Experiments plots stayed white in the dark theme.
    for (const char *name : {"stepPlot", "bodePlot", "spectrumPlot"}) {
        auto *experiment = window.findChild<QCustomPlot *>(QString::fromLatin1(name));
        QVERIFY2(experiment, name);
        experiment->replot();
        QVERIFY2(QColor(experiment->grab().toImage().pixel(3, 3)).lightness() < 60, name);
        for (QCPAxisRect *rect : experiment->axisRects())
            QCOMPARE(rect->axis(QCPAxis::atLeft)->tickLabelColor(),
                     QApplication::palette().color(QPalette::Text));
    }

    window.findChild<QAction *>(QStringLiteral("theme_light"))->trigger();
    QVERIFY(!theme->isDark());
    QVERIFY2(background() > 200, "the plots' background follows the light theme");
    QCOMPARE(y->tickLabelColor(), QApplication::palette().color(QPalette::Text));

    window.findChild<QAction *>(QStringLiteral("theme_system"))->trigger();
    QCOMPARE(QApplication::palette().color(QPalette::Window), systemWindow);
    QCOMPARE(theme->isDark(), systemWindow.lightness() < 128);
}

void TestTheme::widgetsStayReadable_data()
{
    QTest::addColumn<int>("choice");
    QTest::newRow("light") << int(ThemeController::Choice::Light);
    QTest::newRow("dark") << int(ThemeController::Choice::Dark);
}

void TestTheme::widgetsStayReadable()
{
    QFETCH(int, choice);
    MainWindow window;
    ThemeController *theme = showIn(window, choice);
    QVERIFY(theme);
    QApplication::processEvents();
    int checked = 0;
    // The plots' legends: their text against their own background.
    auto *panel = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"));
    panel->customPlot()->replot();
    const QImage plots = panel->customPlot()->grab().toImage();
    for (PlotPanel::Plot kind :
         {PlotPanel::Plot::Angle, PlotPanel::Plot::Torque, PlotPanel::Plot::Reference}) {
        const QRect r = panel->legend(kind)->outerRect().adjusted(2, 2, -2, -2);
        const double ratio = textContrast(plots.copy(r));
        QVERIFY2(
            ratio >= 3.0,
            qPrintable(
                QStringLiteral("legend %1: contrast %2").arg(int(kind)).arg(ratio, 0, 'f', 2)));
        ++checked;
    }
    for (QWidget *w : window.findChildren<QWidget *>()) {
        if (!w->isVisibleTo(&window) || !w->isEnabled() || w->width() < 4 || w->height() < 4)
            continue;
        if (textOf(w).trimmed().isEmpty())
            continue;
        const double ratio = textContrast(w->grab().toImage());
        QVERIFY2(ratio >= 3.0,
                 qPrintable(QStringLiteral("%1 \"%2\" (%3): contrast %4")
                                .arg(QString::fromLatin1(w->metaObject()->className()), textOf(w),
                                     w->objectName())
                                .arg(ratio, 0, 'f', 2)));
        ++checked;
    }
    QVERIFY2(checked >= 10, qPrintable(QString::number(checked)));
    theme->setChoice(ThemeController::Choice::System);
}

void TestTheme::dataColoursReadOnBoth()
{
    const QRgb light = ThemeController::lightPalette().color(QPalette::Base).rgb();
    const QRgb dark = ThemeController::darkPalette().color(QPalette::Base).rgb();
    QList<QColor> colours{palette::kEvent,      palette::kLivePoint, palette::kLimit,
                          palette::kSlotB,      palette::kMeasure,   palette::kInertialTerm,
                          palette::kDampingTerm};
    for (Channel c : kAllChannels)
        colours.append(palette::channel(c));
    for (const QColor &c : colours) {
        const double l = luminance(c.rgb());
        QVERIFY2(contrast(l, luminance(light)) >= 3.0, qPrintable(c.name()));
        QVERIFY2(contrast(l, luminance(dark)) >= 3.0, qPrintable(c.name()));
    }
    // The translucent dead-zone band, once 1.4:1 on the dark plots (barely seen): composited,
    // it stands apart from either background.
    const QColor band = palette::kDeadZone;
    for (const QRgb base : {light, dark}) {
        const double a = band.alphaF();
        const QColor over =
            QColor::fromRgbF(float(band.redF() * a + qRed(base) / 255.0 * (1 - a)),
                             float(band.greenF() * a + qGreen(base) / 255.0 * (1 - a)),
                             float(band.blueF() * a + qBlue(base) / 255.0 * (1 - a)));
        const double ratio = contrast(luminance(over.rgb()), luminance(base));
        QVERIFY2(ratio >= 1.8, qPrintable(QString::number(ratio)));
    }
    // The live operating point: ringed in the theme's text colour, which stands out on its plot.
    for (const QPalette &p : {ThemeController::lightPalette(), ThemeController::darkPalette()}) {
        const QCPScatterStyle dot = plottheme::livePointStyle(p);
        QVERIFY(contrast(luminance(dot.pen().color().rgb()),
                         luminance(p.color(QPalette::Base).rgb())) >= 7.0);
        QVERIFY(dot.size() >= 10);
    }
    // The editor's status texts, on the window colour of either theme.
    const QRgb lightWindow = ThemeController::lightPalette().color(QPalette::Window).rgb();
    const QRgb darkWindow = ThemeController::darkPalette().color(QPalette::Window).rgb();
    for (const QColor &c : {palette::kProblemText, palette::kCautionText, palette::kEditedMark}) {
        const double l = luminance(c.rgb());
        QVERIFY2(contrast(l, luminance(lightWindow)) >= 3.0, qPrintable(c.name()));
        QVERIFY2(contrast(l, luminance(darkWindow)) >= 3.0, qPrintable(c.name()));
    }
}

void TestTheme::derivedFiguresFollowTheTheme_data()
{
    QTest::addColumn<int>("from");
    QTest::addColumn<int>("to");
    QTest::newRow("light to dark")
        << int(ThemeController::Choice::Light) << int(ThemeController::Choice::Dark);
    QTest::newRow("dark to light")
        << int(ThemeController::Choice::Dark) << int(ThemeController::Choice::Light);
}

// The bar under the parameter editor (ω_n, ζ, the peak's bar, the warnings) takes the theme's
// colours when the theme is switched, and its texts read at least 3:1 on either.
void TestTheme::derivedFiguresFollowTheTheme()
{
    QFETCH(int, from);
    QFETCH(int, to);
    MainWindow window;
    ThemeController *theme = showIn(window, from);
    QVERIFY(theme);
    auto *view = window.findChild<DerivedFiguresView *>();
    QVERIFY(view);
    // Every warning shown: the peak above tau_limit, ζ below the ringing bound, chatter.
    DerivedFigures figures{.omega_n = 95,
                           .zeta = 0.1,
                           .timeConstant = 0.05,
                           .peakTauRec = 0.55,
                           .peakAngle = 1.57,
                           .tauLimit = 0.44};
    view->setFigures(figures, true);
    view->setChatter(12.0, 0.02);
    theme->setChoice(static_cast<ThemeController::Choice>(to));
    QApplication::processEvents();
    QVERIFY(view->isShowingSaturation() && view->isShowingRinging() && view->isShowingChatter());
    const bool dark = theme->isDark();
    auto followsTheme = [dark](QRgb background) {
        return dark ? QColor(background).lightness() < 128 : QColor(background).lightness() > 128;
    };

    int labels = 0;
    for (QLabel *label : view->findChildren<QLabel *>()) {
        if (!label->isVisibleTo(&window) || label->text().isEmpty())
            continue;
        const QImage image = label->grab().toImage();
        const double ratio = textContrast(image);
        QVERIFY2(
            ratio >= 3.0,
            qPrintable(
                QStringLiteral("\"%1\": contrast %2").arg(label->text()).arg(ratio, 0, 'f', 2)));
        if (label->objectName().startsWith(QLatin1String("warning_")))
            QVERIFY2(followsTheme(mostCommon(image)), qPrintable(label->text()));
        ++labels;
    }
    QCOMPARE(labels, 12); // 4 names, 4 figures, the peak's percentage, 3 warnings
    const QRect area(view->mapTo(&window, QPoint()), view->size());
    QVERIFY2(followsTheme(mostCommon(window.grab(area).toImage())), "the view's background");

    auto *bar = view->findChild<QProgressBar *>(QStringLiteral("figure_peak_bar"));
    QVERIFY(bar);
    QVERIFY(!bar->isTextVisible()); // its percentage is a label beside it, checked above
    // A peak at 30 % of the limit: the empty part of the groove has the theme's background.
    figures.peakTauRec = 0.132;
    view->setFigures(figures, true);
    QApplication::processEvents();
    QVERIFY(!view->isShowingSaturation());
    const QImage part = bar->grab().toImage();
    QVERIFY2(followsTheme(part.pixel(part.width() * 9 / 10, part.height() / 2)),
             "the bar's groove");
    // The chunk against the groove, from either theme's palette (red once it saturates).
    for (const QPalette &p : {ThemeController::lightPalette(), ThemeController::darkPalette()}) {
        const double groove = luminance(p.color(QPalette::Base).rgb());
        QVERIFY(contrast(groove, luminance(p.color(QPalette::Highlight).rgb())) >= 3.0);
        QVERIFY(contrast(groove, luminance(palette::kLimit.rgb())) >= 3.0);
    }
    theme->setChoice(ThemeController::Choice::System);
}

void TestTheme::choiceIsSaved()
{
    {
        MainWindow window;
        window.findChild<QAction *>(QStringLiteral("theme_dark"))->trigger();
        window.close(); // saves the settings
    }
    QCOMPARE(QSettings().value(QStringLiteral("view/theme")).toString(), QStringLiteral("dark"));
    {
        MainWindow window;
        auto *theme = window.findChild<ThemeController *>(QStringLiteral("themeController"));
        QCOMPARE(theme->choice(), ThemeController::Choice::Dark);
        QVERIFY(window.findChild<QAction *>(QStringLiteral("theme_dark"))->isChecked());
        theme->setChoice(ThemeController::Choice::System);
    }
    QCOMPARE(ThemeController::fromKey(QStringLiteral("nonsense")), ThemeController::Choice::System);
}

QTEST_MAIN(TestTheme)
#include "tst_theme.moc"
