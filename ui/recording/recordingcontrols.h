// The record button and what is being recorded: elapsed time, size, file, or why it stopped.
//
// The session writes the file; this widget only asks for a path and shows
// DeviceClient::recordingChanged.
#pragma once

#include "session/sessiontypes.h"
#include "telemetry/recordingtrigger.h"

#include <QWidget>

#include <functional>
#include <optional>

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

    //! Asks how to record, given the current plan; nullopt = cancelled. Replaceable for tests.
    using PlanChooser = std::function<std::optional<RecordingPlan>(const RecordingPlan &)>;

    explicit RecordingControls(QWidget *parent = nullptr);

    //! hatpic-YYYYMMDD-HHMMSS.csv in `directory` (the documents folder when empty).
    static QString suggestedPath(const QString &directory = {});
    //! `path` when its folder exists, else the same file name in the home folder: a file
    //! dialog given a missing folder (a fresh account has no Documents) opens in the working
    //! directory, where the file would then land unnoticed.
    static QString inExistingFolder(const QString &path);

    void setPathChooser(PathChooser chooser) { m_chooser = std::move(chooser); }
    void setPlanChooser(PlanChooser chooser) { m_planChooser = std::move(chooser); }
    //! How the next recording starts and how long it runs (the session carries it out).
    void setPlan(const RecordingPlan &plan);
    RecordingPlan plan() const { return m_plan; }
    void setDirectory(const QString &directory) { m_directory = directory; }
    QString directory() const { return m_directory; } //!< of the last recording chosen
    //! Asks which recording to replay, starting in the folder of the last recording made or
    //! opened (what a researcher opens next); remembers its folder. Empty = cancelled.
    QString chooseRecordingToOpen();

    void setStatus(const RecordingStatus &status);
    RecordingStatus status() const { return m_status; }
    //! Why the last recording ended where it did ("Recording ended at the link loss: …"),
    //! shown with "Saved …" until the next recording starts: it is not a passing message.
    void setNote(const QString &note);
    QString note() const { return m_note; }
    void setCanRecord(bool connected);

    QAction *recordAction() const { return m_action; }   //!< Ctrl+R, checkable
    QAction *planAction() const { return m_planAction; } //!< opens the recording options
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
    void onPlanTriggered();
    void refresh();
    QString gapsText() const; //!< " · 2 gaps" after a link loss, else empty

    QAction *m_action = nullptr;
    QAction *m_planAction = nullptr;
    PlanChooser m_planChooser;
    RecordingPlan m_plan;
    QToolButton *m_button = nullptr;
    QLabel *m_label = nullptr;
    PathChooser m_chooser;
    QString m_directory;
    RecordingStatus m_status;
    QString m_note;
    bool m_canRecord = false;
};

} // namespace hatpic
