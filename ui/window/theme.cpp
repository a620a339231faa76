#include "window/theme.h"

#include "plots/plottheme.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QStyle>
#include <QStyleFactory>

namespace hatpic {

namespace {

//! The style the platform gave before any theme was chosen: captured once, at the first use.
const QString &systemStyle()
{
    static const QString style = QApplication::style()->name();
    return style;
}

} // namespace

ThemeController::ThemeController(QWidget *window) : QObject(window)
{
    systemStyle();
    m_menu = new QMenu(tr("&Theme"), window);
    m_menu->setObjectName(QStringLiteral("menu_theme"));
    m_group = new QActionGroup(this);
    m_group->setExclusive(true);
    const std::pair<Choice, QString> entries[] = {{Choice::System, tr("&System")},
                                                  {Choice::Light, tr("&Light")},
                                                  {Choice::Dark, tr("&Dark")}};
    for (const auto &[choice, text] : entries) {
        QAction *action = m_menu->addAction(text);
        action->setObjectName(QStringLiteral("theme_") + key(choice));
        action->setCheckable(true);
        action->setChecked(choice == m_choice);
        action->setData(int(choice));
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, choice] { setChoice(choice); });
    }
    m_menu->actions().constFirst()->setToolTip(tr("Follow the system's light or dark look"));
}

ThemeController::~ThemeController() = default;

void ThemeController::setChoice(Choice choice)
{
    const bool changed = choice != m_choice;
    m_choice = choice;
    for (QAction *action : m_group->actions())
        action->setChecked(action->data().toInt() == int(choice));
    apply();
    if (changed)
        Q_EMIT choiceChanged(choice);
}

bool ThemeController::isDark() const
{
    switch (m_choice) {
    case Choice::Light:
        return false;
    case Choice::Dark:
        return true;
    case Choice::System:
        break;
    }
    return plottheme::isDark(QApplication::palette());
}

void ThemeController::apply()
{
    const QString style = m_choice == Choice::System ? systemStyle() : QStringLiteral("Fusion");
    if (QApplication::style()->name().compare(style, Qt::CaseInsensitive) != 0)
        QApplication::setStyle(style);
    switch (m_choice) {
    case Choice::System:
        // A palette that sets no role (QPalette() is the current one with an empty resolve
        // mask) resolves entirely against the platform's, and again whenever the platform's
        // changes: the look keeps following the system.
        QApplication::setPalette(QPalette());
        break;
    case Choice::Light:
        QApplication::setPalette(lightPalette());
        break;
    case Choice::Dark:
        QApplication::setPalette(darkPalette());
        break;
    }
}

QPalette ThemeController::lightPalette()
{
    QStyle *fusion = QStyleFactory::create(QStringLiteral("Fusion"));
    QPalette palette = fusion ? fusion->standardPalette() : QPalette(QColor(239, 239, 239));
    delete fusion;
    return palette;
}

QPalette ThemeController::darkPalette()
{
    const QColor window(48, 48, 50);
    const QColor base(30, 30, 32);
    const QColor text(232, 232, 232);
    const QColor disabled(140, 140, 140);
    QPalette p;
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, window);
    p.setColor(QPalette::ToolTipBase, window);
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, QColor(160, 160, 160));
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(58, 58, 62));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, QColor(255, 110, 110));
    p.setColor(QPalette::Light, QColor(80, 80, 84));
    p.setColor(QPalette::Midlight, QColor(66, 66, 70));
    p.setColor(QPalette::Mid, QColor(40, 40, 42));
    p.setColor(QPalette::Dark, QColor(24, 24, 26));
    p.setColor(QPalette::Shadow, QColor(10, 10, 10));
    p.setColor(QPalette::Highlight, QColor(42, 110, 190));
    p.setColor(QPalette::HighlightedText, QColor(255, 255, 255));
    p.setColor(QPalette::Link, QColor(110, 170, 255));
    p.setColor(QPalette::LinkVisited, QColor(180, 140, 255));
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    p.setColor(QPalette::Disabled, QPalette::Base, window);
    return p;
}

QString ThemeController::key(Choice choice)
{
    switch (choice) {
    case Choice::Light:
        return QStringLiteral("light");
    case Choice::Dark:
        return QStringLiteral("dark");
    case Choice::System:
        break;
    }
    return QStringLiteral("system");
}

ThemeController::Choice ThemeController::fromKey(const QString &key)
{
    if (key == QLatin1String("light"))
        return Choice::Light;
    if (key == QLatin1String("dark"))
        return Choice::Dark;
    return Choice::System;
}

} // namespace hatpic
