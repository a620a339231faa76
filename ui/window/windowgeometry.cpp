#include "window/windowgeometry.h"

#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>

#include <algorithm>

namespace hatpic {

namespace {

//! The available geometry of the screen showing `rect` (else the window's, else primary).
QRect availableGeometryFor(const QWidget *window, const QRect &rect)
{
    const QScreen *on = rect.isValid() ? QGuiApplication::screenAt(rect.center()) : nullptr;
    if (!on)
        on = window->screen();
    if (!on)
        on = QGuiApplication::primaryScreen();
    return on ? on->availableGeometry() : QRect();
}

} // namespace

QRect fittedInto(const QRect &rect, const QRect &available)
{
    if (!available.isValid())
        return rect;
    QRect fitted(rect.topLeft(), rect.size().boundedTo(available.size()));
    fitted.moveLeft(std::clamp(fitted.left(), available.left(),
                               available.left() + available.width() - fitted.width()));
    fitted.moveTop(std::clamp(fitted.top(), available.top(),
                              available.top() + available.height() - fitted.height()));
    return fitted;
}

bool restoreWindowGeometry(QMainWindow *window, const QSettings &settings)
{
    // The window's own rectangle, fitted into the screen both when saved and when restored;
    // "window/geometry" is what versions before it saved (opaque, and never fitted).
    const QRect saved = settings.value(QStringLiteral("window/rect")).toRect();
    if (saved.isValid()) {
        window->setGeometry(fittedInto(saved, availableGeometryFor(window, saved)));
        if (settings.value(QStringLiteral("window/maximized"), false).toBool())
            window->setWindowState(window->windowState() | Qt::WindowMaximized);
        return true;
    }
    if (window->restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) {
        if (!window->isMaximized() && !window->isFullScreen())
            window->setGeometry(
                fittedInto(window->geometry(), availableGeometryFor(window, window->geometry())));
        return true;
    }
    return false;
}

void resizeToDefault(QMainWindow *window)
{
    const QRect wanted(QPoint(0, 0), QSize(1400, 900));
    window->resize(fittedInto(wanted, availableGeometryFor(window, QRect())).size());
}

void fitFrameIntoScreen(QMainWindow *window)
{
    if (!window->isVisible() || window->isMaximized() || window->isFullScreen())
        return;
    const QRect frame = window->frameGeometry();
    const QRect inner = window->geometry();
    const QRect fitted = fittedInto(frame, availableGeometryFor(window, frame));
    if (fitted == frame)
        return;
    // The same frame around a smaller or moved window.
    const QMargins margins(inner.left() - frame.left(), inner.top() - frame.top(),
                           frame.right() - inner.right(), frame.bottom() - inner.bottom());
    window->setGeometry(fitted.marginsRemoved(margins));
}

void saveWindowGeometry(const QMainWindow *window, QSettings &settings)
{
    const QRect normal = window->isMaximized() || window->isFullScreen() ? window->normalGeometry()
                                                                         : window->geometry();
    settings.setValue(QStringLiteral("window/rect"),
                      fittedInto(normal, availableGeometryFor(window, normal)));
    settings.setValue(QStringLiteral("window/maximized"), window->isMaximized());
    settings.remove(QStringLiteral("window/geometry"));
}

} // namespace hatpic
