// The record button and what is being recorded: elapsed time, size, file, or why it stopped.
//
// The session writes the file; this widget only asks for a path and shows
// DeviceClient::recordingChanged.
#pragma once

#include "session/sessiontypes.h"

#include <QWidget>

#include <functional>

class QAction;
class QLabel;
class QToolButton;

namespace hatpic {

class RecordingControls : public QWidget
{
    Q_OBJECT
public:
    //! Asks where to record, given a suggested path; empty = cancelled. Replaceable for tests.
    using PathChooser = std::function<QString(const QString &suggested)>;

    explicit RecordingControls(QWidget *parent = nullptr);

    //! hatpic-YYYYMMDD-HHMMSS.csv in `directory` (the documents folder when empty).
    static QString suggestedPath(const QString &directory = {});
    //! `path` when its folder exists, else the same file name in the home folder: a file
    //! dialog given a missing folder (a fresh account has no Documents) opens in the working
    //! directory, where the file would then land unnoticed.
    static QString inExistingFolder(const QString &path);

    void setPathChooser(PathChooser chooser) { m_chooser = std::move(chooser); }
    void setDirectory(const QString &directory) { m_directory = directory; }
    QString directory() const { return m_directory; } //!< of the last recording chosen
    //! Asks which recording to replay, starting in the folder of the last recording made or
    //! opened (what a researcher opens next); remembers its folder. Empty = cancelled.
    QString chooseRecordingToOpen();

    void setStatus(const RecordingStatus &status);
    RecordingStatus status() const { return m_status; }
    void setCanRecord(bool connected);

    QAction *recordAction() const { return m_action; } //!< Ctrl+R, checkable
    QString statusText() const;

    //! Human sizes: "812 B", "3.4 kB", "12.1 MB".
    static QString formatBytes(qint64 bytes);
    //! "00:07", "12:03", "1:02:03".
    static QString formatDuration(double seconds);

Q_SIGNALS:
    void startRequested(const QString &path);
    void stopRequested();

private:
    void onTriggered();
    void refresh();

    QAction *m_action = nullptr;
    QToolButton *m_button = nullptr;
    QLabel *m_label = nullptr;
    PathChooser m_chooser;
    QString m_directory;
    RecordingStatus m_status;
    bool m_canRecord = false;
};

} // namespace hatpic
