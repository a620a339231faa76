// WheelGuard: the wheel scrolls a panel past its fields and changes a value only in the field
// that has the focus. Real widgets in a real scroll area, wheel events delivered as the window
// system delivers them (spontaneous, to the widget under the pointer, offered to its parents).
#include "plots/qcp.h"
#include "wheelevent.h"
#include "window/wheelguard.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QTest>
#include <QVBoxLayout>

using namespace hatpic;
using namespace hatpic::test;

namespace {

//! A tall column of fields of one kind in a scroll area, like the Parameters panel.
struct Panel
{
    QScrollArea scroll;
    QList<QWidget *> fields;

    explicit Panel(const QString &kind)
    {
        auto *content = new QWidget;
        auto *column = new QVBoxLayout(content);
        for (int i = 0; i < 30; ++i) {
            QWidget *field = nullptr;
            if (kind == u"spin box") {
                auto *spin = new QDoubleSpinBox(content);
                spin->setRange(0, 100);
                spin->setValue(50);
                field = spin;
            } else if (kind == u"slider") {
                auto *slider = new QSlider(Qt::Horizontal, content);
                slider->setRange(0, 100);
                slider->setValue(50);
                field = slider;
            } else {
                auto *combo = new QComboBox(content);
                combo->addItems({QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")});
                combo->setCurrentIndex(1);
                field = combo;
            }
            column->addWidget(field);
            fields << field;
        }
        scroll.setWidget(content);
        scroll.setWidgetResizable(true);
        scroll.resize(300, 200);
        scroll.show();
    }
};

int valueOf(const QWidget *field)
{
    if (const auto *spin = qobject_cast<const QDoubleSpinBox *>(field))
        return int(spin->value());
    if (const auto *slider = qobject_cast<const QSlider *>(field))
        return slider->value();
    return qobject_cast<const QComboBox *>(field)->currentIndex();
}

} // namespace

class TestWheelGuard : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void kinds_data();
    void restingPointerDoesNotEdit_data() { kinds_data(); }
    void restingPointerDoesNotEdit();
    void panelScrollsPastFields_data() { kinds_data(); }
    void panelScrollsPastFields();
    void focusedFieldTakesTheWheel_data() { kinds_data(); }
    void focusedFieldTakesTheWheel();
    void scrollBarKeepsTheWheel();
    void panelScrollsPastAStillPlot();
};

void TestWheelGuard::initTestCase()
{
    WheelGuard::install();
    WheelGuard::install(); // once, however often
}

void TestWheelGuard::kinds_data()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("spin box") << QStringLiteral("spin box");
    QTest::newRow("slider") << QStringLiteral("slider");
    QTest::newRow("combo box") << QStringLiteral("combo box");
}

void TestWheelGuard::restingPointerDoesNotEdit()
{
    QFETCH(QString, kind);
    Panel panel(kind);
    QVERIFY(QTest::qWaitForWindowExposed(&panel.scroll));
    QWidget *field = panel.fields.at(1); // the first may have the window's initial focus
    QVERIFY(!field->hasFocus());
    const int before = valueOf(field);
    for (int i = 0; i < 3; ++i)
        turnWheel(field, field->rect().center(), -120);
    QCOMPARE(valueOf(field), before);
    QVERIFY(!field->hasFocus()); // the wheel gives no focus either
    QVERIFY(!(field->focusPolicy() & (int(Qt::WheelFocus) & ~int(Qt::StrongFocus))));
}

void TestWheelGuard::panelScrollsPastFields()
{
    QFETCH(QString, kind);
    Panel panel(kind);
    QVERIFY(QTest::qWaitForWindowExposed(&panel.scroll));
    QScrollBar *bar = panel.scroll.verticalScrollBar();
    QVERIFY(bar->maximum() > 0);
    QCOMPARE(bar->value(), 0);
    // The pointer stays where it is while the fields pass under it.
    const QPoint pointer = panel.scroll.viewport()->rect().center();
    for (int i = 0; i < 6; ++i) {
        QWidget *under = panel.scroll.viewport()->childAt(pointer);
        QVERIFY(under);
        turnWheel(panel.scroll.viewport(), pointer, -120);
    }
    QVERIFY(bar->value() > 0);
    for (QWidget *field : std::as_const(panel.fields))
        QCOMPARE(valueOf(field), kind == u"combo box" ? 1 : 50);
}

void TestWheelGuard::focusedFieldTakesTheWheel()
{
    QFETCH(QString, kind);
    Panel panel(kind);
    QVERIFY(QTest::qWaitForWindowExposed(&panel.scroll));
    panel.scroll.activateWindow();
    QWidget *field = panel.fields.first();
    field->setFocus(Qt::TabFocusReason);
    QTRY_VERIFY(field->hasFocus());
    const int before = valueOf(field);
    turnWheel(field, field->rect().center(), 120);
    QVERIFY2(valueOf(field) != before, qPrintable(QString::number(valueOf(field))));
    QCOMPARE(panel.scroll.verticalScrollBar()->value(), 0);
}

void TestWheelGuard::scrollBarKeepsTheWheel()
{
    Panel panel(QStringLiteral("spin box"));
    QVERIFY(QTest::qWaitForWindowExposed(&panel.scroll));
    QScrollBar *bar = panel.scroll.verticalScrollBar();
    turnWheel(bar, bar->rect().center(), -120);
    QVERIFY(bar->value() > 0);
}

// Issue 27: the Bridge panel's energy plot (a QCustomPlot that does not zoom) took every wheel
// turn, and the panel stopped scrolling under the pointer. A plot that zooms keeps the wheel.
void TestWheelGuard::panelScrollsPastAStillPlot()
{
    QScrollArea scroll;
    auto *content = new QWidget;
    auto *column = new QVBoxLayout(content);
    auto *still = new QCustomPlot(content);
    still->setMinimumHeight(300);
    auto *zooming = new QCustomPlot(content);
    zooming->setMinimumHeight(300);
    zooming->setInteractions(QCP::iRangeZoom);
    column->addWidget(still);
    column->addWidget(zooming);
    scroll.setWidget(content);
    scroll.setWidgetResizable(true);
    scroll.resize(300, 200);
    scroll.show();
    QVERIFY(QTest::qWaitForWindowExposed(&scroll));
    QScrollBar *bar = scroll.verticalScrollBar();
    QVERIFY(bar->maximum() > 0);
    turnWheel(still, still->rect().center(), -120);
    QVERIFY(bar->value() > 0);
    bar->setValue(bar->maximum());
    const QCPRange before = zooming->xAxis->range();
    turnWheel(zooming, zooming->rect().center(), 120);
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY(zooming->xAxis->range().size() < before.size());
}

QTEST_MAIN(TestWheelGuard)
#include "tst_wheelguard.moc"
