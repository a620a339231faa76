// The main window's rectangle in the settings: fitted into the screen both when saved and when
// restored, so that no screen ever gets a window larger than itself (issue 10).
#pragma once

#include <QRect>

class QMainWindow;
class QSettings;

namespace hatpic {

//! `rect` made no larger than `available` and moved inside it.
QRect fittedInto(const QRect &rect, const QRect &available);

//! Restores the saved rectangle (or what versions before it saved), fitted into its screen;
//! false when nothing was saved (the first launch).
bool restoreWindowGeometry(QMainWindow *window, const QSettings &settings);
void saveWindowGeometry(const QMainWindow *window, QSettings &settings);

//! The first launch's size: 1400×900, fitted into the window's screen (a 1280×720 screen gets
//! a window no larger than itself).
void resizeToDefault(QMainWindow *window);

//! Moves and shrinks a shown window so that its frame (a window manager's title bar and
//! borders included) lies inside its screen's available area; a maximized or full-screen
//! window is left alone.
void fitFrameIntoScreen(QMainWindow *window);

} // namespace hatpic
