// The window's status bar messages (pushes, profiles, the link). The readouts that always stand
// on the right (the simulated hand, the link statistics) sit in one container; a message too
// long for the room beside them hides the container while it shows, instead of being cut off
// (issue 21: push messages were cut at 1280×720). A message longer than the whole bar is elided,
// with all of it in the bar's tooltip. Longer messages stay longer.
#pragma once

#include <QObject>
#include <QString>

class QStatusBar;
class QWidget;

namespace hatpic {

class StatusLine : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinMs = 6000;   //!< the least a message stays [ms]
    static constexpr int kMsPerChar = 60; //!< reading time beyond that [ms per character]

    //! Adds the container of the right-hand readouts to `bar` (object name "statusReadouts").
    explicit StatusLine(QStatusBar *bar);

    //! Where the right-hand readouts go (add them to its layout).
    QWidget *readouts() const { return m_readouts; }
    //! Shows `message` for durationMs(message).
    void show(const QString &message);
    //! The message shown now, whole (empty when none).
    QString message() const { return m_message; }

    static int durationMs(const QString &message);

private:
    QStatusBar *m_bar;
    QWidget *m_readouts;
    QString m_message;
};

} // namespace hatpic
