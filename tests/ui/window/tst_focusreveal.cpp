// A field given the keyboard focus is scrolled into view (issue 27: Alt+1…9 put the cursor in a
// field out of sight): real widgets offscreen, a form in a short scroll area, and in nested
// ones; a mouse click scrolls nothing.
#include "window/focusreveal.h"

#include <QApplication>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QTest>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

using namespace hatpic;

namespace {

//! True when `w` lies wholly inside the viewport of `area`.
bool inView(const QScrollArea *area, const QWidget *w)
{
    const QRect r(w->mapTo(area->viewport(), QPoint()), w->size());
    return area->viewport()->rect().contains(r);
}

} // namespace

class TestFocusReveal : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { FocusReveal::install(); }

    void focusScrollsTheFieldIntoView()
    {
        QScrollArea area;
        auto *form = new QWidget;
        auto *layout = new QVBoxLayout(form);
        QList<QLineEdit *> fields;
        for (int i = 0; i < 40; ++i)
            layout->addWidget(fields.emplace_back(new QLineEdit(form)));
        area.setWidget(form);
        area.setWidgetResizable(true);
        area.resize(300, 150);
        area.show();
        QVERIFY(QTest::qWaitForWindowExposed(&area));
        area.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&area));
        QLineEdit *last = fields.last();
        QVERIFY(!inView(&area, last));
        // A shortcut or a program moves the focus: the field comes into view.
        last->setFocus(Qt::ShortcutFocusReason);
        QVERIFY(inView(&area, last));
        fields.first()->setFocus(Qt::OtherFocusReason);
        QVERIFY(inView(&area, fields.first()));
        QVERIFY(!inView(&area, last));
        // A click: what was clicked is where the pointer is; nothing jumps.
        const int before = area.verticalScrollBar()->value();
        fields[20]->setFocus(Qt::MouseFocusReason);
        QCOMPARE(area.verticalScrollBar()->value(), before);
    }

    // Issue 27: 21 of 24 Tab stops after the editor showed no focus. A widget reached from the
    // keyboard is ringed; a click leaves the look alone; the ring goes with the focus.
    void keyboardFocusIsRinged()
    {
        QWidget window;
        auto *layout = new QVBoxLayout(&window);
        auto *first = new QLineEdit(&window);
        auto *button = new QToolButton(&window); // Fusion draws no focus on a tool button
        button->setText(QStringLiteral("Tool"));
        button->setFocusPolicy(Qt::StrongFocus);
        auto *last = new QLineEdit(&window);
        for (QWidget *w : {static_cast<QWidget *>(first), static_cast<QWidget *>(button),
                           static_cast<QWidget *>(last)})
            layout->addWidget(w);
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        first->setFocus(Qt::MouseFocusReason);
        QVERIFY(!FocusReveal::ring());
        QTest::keyClick(first, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), button);
        QWidget *ring = FocusReveal::ring();
        QVERIFY(ring);
        QCOMPARE(ring->parentWidget(), button->parentWidget());
        QVERIFY(ring->geometry().contains(button->geometry()));
        QVERIFY(ring->geometry().width() <= button->width() + 2 * FocusReveal::kRingWidth);
        // Drawn in the highlight colour, on top of the button's edge.
        const QImage image = window.grab(ring->geometry()).toImage();
        const QColor highlight = ring->palette().color(QPalette::Highlight);
        int ringed = 0;
        for (int x = 0; x < image.width(); ++x)
            ringed += QColor(image.pixel(x, 0)).blue() > 120 &&
                      std::abs(QColor(image.pixel(x, 0)).hue() - highlight.hue()) < 30;
        QVERIFY2(ringed > image.width() / 2, qPrintable(QString::number(ringed)));
        QTest::keyClick(button, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), last);
        QVERIFY(FocusReveal::ring()->geometry().contains(last->geometry()));
        QTest::mouseClick(first, Qt::LeftButton);
        QCOMPARE(QApplication::focusWidget(), first);
        QVERIFY(!FocusReveal::ring());
    }

    void nestedScrollAreas()
    {
        QScrollArea outer;
        auto *page = new QWidget;
        auto *pageLayout = new QVBoxLayout(page);
        pageLayout->addSpacing(600);
        auto *inner = new QScrollArea(page);
        inner->setMinimumHeight(120);
        auto *form = new QWidget;
        auto *layout = new QVBoxLayout(form);
        QLineEdit *target = nullptr;
        for (int i = 0; i < 30; ++i)
            layout->addWidget(target = new QLineEdit(form));
        inner->setWidget(form);
        inner->setWidgetResizable(true);
        pageLayout->addWidget(inner);
        outer.setWidget(page);
        outer.setWidgetResizable(true);
        outer.resize(300, 200);
        outer.show();
        QVERIFY(QTest::qWaitForWindowExposed(&outer));
        outer.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&outer));
        target->setFocus(Qt::TabFocusReason);
        QVERIFY(inView(inner, target));
        QVERIFY(inView(&outer, target));
    }
};

QTEST_MAIN(TestFocusReveal)
#include "tst_focusreveal.moc"
