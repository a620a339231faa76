// Profile files for the window's tuning: Open, Save, Save As, recent files, built-in presets,
// and two slots (A/B) to compare tunings with one key. Owns no widgets except its menus.
#pragma once

#include "profile/profile.h"

#include <QMessageBox>
#include <QObject>
#include <QStringList>

#include <array>
#include <functional>
#include <memory>

class QAction;
class QMenu;
class QUndoStack;
class QWidget;

namespace hatpic {

class TuningModel;

class ProfileController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxRecentFiles = 8;
    static constexpr int kSlotCount = 2; //!< A and B
    //! QSettings key of the recent-file list (most recent first).
    static constexpr char16_t kRecentKey[] = u"profiles/recent";
    static constexpr char16_t kLastDirKey[] = u"profiles/lastDir";
    //! QSettings key of "push on switch" (bool).
    static constexpr char16_t kPushOnSwitchKey[] = u"profiles/pushOnSwitch";

    //! Answers "save changes to X?" with Save, Discard or Cancel. Replaceable for tests.
    using Question = std::function<QMessageBox::StandardButton(const QString &text)>;

    //! `model` and `undo` are the window's (its tuning and its one undo history) and must
    //! outlive the controller: the active slot is the model's edited tuning, a load or a switch
    //! an undo step on `undo`.
    ProfileController(TuningModel *model, QUndoStack *undo, QWidget *dialogParent,
                      QObject *parent = nullptr);
    ~ProfileController() override;

    QAction *openAction() const { return m_openAction; }     //!< Ctrl+O
    QAction *saveAction() const { return m_saveAction; }     //!< Ctrl+S
    QAction *saveAsAction() const { return m_saveAsAction; } //!< Ctrl+Shift+S
    QAction *abToggleAction() const { return m_abAction; }   //!< Ctrl+B
    //! Checkable, remembered: switching slots (Ctrl+B, or undo past a switch) also pushes the
    //! slot that becomes active (TuningModel::push), when a push is possible.
    QAction *pushOnSwitchAction() const { return m_pushOnSwitchAction; }
    QMenu *recentMenu() const { return m_recentMenu.get(); }
    QMenu *presetsMenu() const { return m_presetsMenu.get(); }

    //! Loads a profile into the active slot (one undo step). A refused file changes nothing;
    //! its errors (all of them, as the core reports them) go to `error`, or to a message box
    //! when `error` is null.
    bool openFile(const QString &path, QString *error = nullptr);
    //! Saves the active slot to `path` (atomically). Refuses an invalid parameter set.
    bool saveTo(const QString &path, QString *error = nullptr);
    bool save();   //!< to the slot's file, or asks for one
    bool saveAs(); //!< asks for a file
    //! Loads a built-in preset into the active slot.
    bool loadPreset(const QString &name);
    //! Asks for every slot with unsaved changes: Save / Discard / Cancel. False on cancel.
    bool maybeSave();

    //! What `slot` has unsaved, by name: "K_max, N", "a bridge setting", "the notes".
    QStringList unsavedParts(int slot) const;
    //! A preset's description for its menu entry: the first clause of its notes, at most 64
    //! characters ("A knob that clicks").
    static QString presetSummary(const QString &notes);
    bool isModified() const; //!< the active slot differs from its file (or preset)
    bool isModified(int slot) const;
    QString profileName() const;
    QString filePath() const;
    int activeSlot() const { return m_active; }
    static QString slotName(int slot); //!< "A" or "B"
    //! "Notchy* [A] — HATPIC Tuner": name, '*' when modified, active slot.
    QString windowTitle() const;
    QStringList recentFiles() const;

    //! Switches A ↔ B as one undo step. The first switch to B starts B as a copy of A.
    void toggleSlot();
    //! Makes `slot` active without an undo step (used by the undo command and the blind
    //! study). `pushOnSwitch` false: never pushes, whatever pushOnSwitchAction() says.
    void activateSlot(int slot, bool pushOnSwitch = true);
    //! Whether `slot` holds a profile (B does after the first switch).
    bool isSlotUsed(int slot) const;
    //! A slot's profile as it is now (the active slot's is the model's edited tuning), unsaved
    //! changes in.
    Profile slotProfile(int slot) const { return currentProfile(slot); }

    //! The active slot's notes (the profile's "notes"), as edited.
    QString notes() const { return m_notes; }
    //! Edits the active slot's notes as an undo step (typing merges into one); the '*' counts
    //! them and Save writes them.
    void setNotes(const QString &notes);
    //! Sets the notes without an undo step (used by the undo command).
    void applyNotes(const QString &notes);

    void setQuestion(Question question) { m_question = std::move(question); }

    //! The robot bridge's settings of the active slot (the profile's host.bridge), as the
    //! Bridge panel holds them; Save writes them, the '*' counts them. The domain id is no
    //! part of a profile and is dropped.
    void setBridgeSettings(const bridge::BridgeSettings &settings);
    const bridge::BridgeSettings &bridgeSettings() const { return m_bridge; }

Q_SIGNALS:
    void titleChanged(const QString &title);
    void statusMessage(const QString &message);
    void activeSlotChanged(int slot);
    //! Anything in either slot may have changed (an edit, a load, a save, a switch).
    void slotsChanged();
    //! The active slot's notes changed (an edit, undo, a load, a switch).
    void notesChanged(const QString &notes);
    //! A profile (or the other slot) brought its own bridge settings.
    void bridgeSettingsLoaded(const hatpic::bridge::BridgeSettings &settings);

private:
    struct Slot
    {
        Profile saved;   //!< as last opened/saved (or the preset); the '*' compares against it
        Profile working; //!< the values while the slot is not the active one
        QString path;    //!< empty: never saved
        bool used = false;
    };

    Profile currentProfile(int slot) const;
    bool saveSlot(int slot, const QString &path, QString *error);
    bool saveSlotInteractive(int slot, bool askPath);
    bool maybeSaveSlot(int slot);
    void load(const Profile &profile, const QString &path, const QString &undoText);
    void addRecent(const QString &path);
    void rebuildRecentMenu();
    void rebuildPresetsMenu();
    void updateTitle();

    TuningModel *m_model;
    QUndoStack *m_undo;
    QWidget *m_dialogParent;
    std::array<Slot, kSlotCount> m_slots;
    int m_active = 0;
    bridge::BridgeSettings m_bridge; //!< the active slot's
    QString m_notes;                 //!< the active slot's
    QString m_title;
    Question m_question;

    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
    QAction *m_saveAsAction = nullptr;
    QAction *m_abAction = nullptr;
    QAction *m_pushOnSwitchAction = nullptr;
    std::unique_ptr<QMenu> m_recentMenu;
    std::unique_ptr<QMenu> m_presetsMenu;
};

} // namespace hatpic
