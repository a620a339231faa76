// The light/dark theme: follows the system, or is chosen (View → Theme: System, Light, Dark).
// Qt 6.4 has no QStyleHints::colorScheme, so the system's scheme is read from its palette (a
// window colour darker than mid-grey is dark). Light and Dark use the Fusion style with a
// palette of their own; System restores the style and palette the platform gave. The plots
// follow through their palette (plots/plottheme.h).
#pragma once

#include <QObject>
#include <QPalette>
#include <QString>

class QActionGroup;
class QMenu;
class QWidget;

namespace hatpic {

class ThemeController : public QObject
{
    Q_OBJECT
public:
    enum class Choice { System, Light, Dark };

    //! The menu is owned by `window`'s lifetime (this object is its child).
    explicit ThemeController(QWidget *window);
    ~ThemeController() override;

    QMenu *menu() const { return m_menu; }
    void setChoice(Choice choice);
    Choice choice() const { return m_choice; }
    //! Whether what is shown is dark (for System: whether the system's palette is).
    bool isDark() const;

    static QPalette darkPalette();
    static QPalette lightPalette();
    //! "system", "light", "dark" (the settings' value); unknown text is System.
    static QString key(Choice choice);
    static Choice fromKey(const QString &key);

Q_SIGNALS:
    void choiceChanged(hatpic::ThemeController::Choice choice);

private:
    void apply();

    QMenu *m_menu = nullptr;
    QActionGroup *m_group = nullptr;
    Choice m_choice = Choice::System;
};

} // namespace hatpic
