#include "profiles/profilecontroller.h"

#include "profiles/abswitchcommand.h"
#include "profiles/noteseditcommand.h"
#include "tuning/tuningmodel.h"

#include <algorithm>

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QUndoStack>
#include <QWidget>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

const QString kUntitled = QStringLiteral("Untitled");
const QString kAppName = QStringLiteral("HATPIC Tuner");

QString settingsKey(const char16_t *key)
{
    return QString::fromUtf16(key);
}

} // namespace

ProfileController::ProfileController(TuningModel *model, QUndoStack *undo, QWidget *dialogParent,
                                     QObject *parent)
    : QObject(parent), m_model(model), m_undo(undo), m_dialogParent(dialogParent)
{
    // Enter (the default button) cancels: neither the file is overwritten nor the edits lost
    // by a key pressed without reading the question.
    m_question = [this](const QString &text) {
        return QMessageBox::question(m_dialogParent, tr("Unsaved changes"), text,
                                     QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                     QMessageBox::Cancel);
    };

    // Slot A starts as the tuning edited now, untitled and unmodified.
    Slot &a = m_slots[0];
    a.saved.name = kUntitled;
    a.saved.device = model->edited().device;
    a.saved.host = model->edited().host;
    a.working = a.saved;
    a.used = true;

    m_openAction = new QAction(tr("&Open Profile…"), this);
    m_openAction->setObjectName(u"action_open_profile"_s);
    m_openAction->setShortcut(QKeySequence::Open);
    connect(m_openAction, &QAction::triggered, this, [this] {
        if (!maybeSaveSlot(m_active))
            return;
        QSettings settings;
        const QString path = QFileDialog::getOpenFileName(
            m_dialogParent, tr("Open profile"), settings.value(settingsKey(kLastDirKey)).toString(),
            tr("HATPIC profiles (*.json);;All files (*)"));
        if (!path.isEmpty())
            openFile(path);
    });
    m_saveAction = new QAction(tr("&Save Profile"), this);
    m_saveAction->setObjectName(u"action_save_profile"_s);
    m_saveAction->setShortcut(QKeySequence::Save);
    connect(m_saveAction, &QAction::triggered, this, &ProfileController::save);
    m_saveAsAction = new QAction(tr("Save Profile &As…"), this);
    m_saveAsAction->setObjectName(u"action_save_profile_as"_s);
    m_saveAsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(m_saveAsAction, &QAction::triggered, this, &ProfileController::saveAs);
    m_abAction = new QAction(tr("Switch A/B"), this);
    m_abAction->setObjectName(u"action_ab_toggle"_s);
    m_abAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_abAction->setToolTip(tr("Switch between the two loaded profiles A and B (Ctrl+B)"));
    connect(m_abAction, &QAction::triggered, this, &ProfileController::toggleSlot);
    m_pushOnSwitchAction = new QAction(tr("Push on A/B Switch"), this);
    m_pushOnSwitchAction->setObjectName(u"action_push_on_switch"_s);
    m_pushOnSwitchAction->setCheckable(true);
    m_pushOnSwitchAction->setChecked(QSettings().value(settingsKey(kPushOnSwitchKey)).toBool());
    m_pushOnSwitchAction->setToolTip(tr("Switching A/B also pushes the slot to the device"));
    connect(m_pushOnSwitchAction, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(settingsKey(kPushOnSwitchKey), on); });
    if (m_dialogParent)
        m_dialogParent->addActions({m_openAction, m_saveAction, m_saveAsAction, m_abAction});

    m_recentMenu = std::make_unique<QMenu>(tr("Open &Recent"));
    m_recentMenu->setObjectName(u"menu_recent_profiles"_s);
    m_presetsMenu = std::make_unique<QMenu>(tr("&Presets"));
    m_presetsMenu->setObjectName(u"menu_presets"_s);
    rebuildRecentMenu();
    rebuildPresetsMenu();

    connect(m_model, &TuningModel::editedChanged, this, &ProfileController::updateTitle);
    updateTitle();
}

ProfileController::~ProfileController() = default;

QString ProfileController::slotName(int slot)
{
    return slot == 0 ? u"A"_s : u"B"_s;
}

Profile ProfileController::currentProfile(int slot) const
{
    Profile p = slot == m_active ? m_slots[slot].saved : m_slots[slot].working;
    p.name = m_slots[slot].saved.name;
    if (slot == m_active) {
        p.notes = m_notes;
        const Tuning &edited = m_model->edited();
        p.device = edited.device;
        p.host = edited.host;
        p.effects = edited.effects;
        p.passivity = edited.passivity;
        p.bridge = m_bridge;
    }
    return p;
}

bool ProfileController::isModified(int slot) const
{
    if (slot < 0 || slot >= kSlotCount || !m_slots[slot].used)
        return false;
    const Profile p = currentProfile(slot);
    const Profile &saved = m_slots[slot].saved;
    return p.device != saved.device || p.host != saved.host || p.effects != saved.effects ||
           p.bridge != saved.bridge || p.notes != saved.notes;
}

QStringList ProfileController::unsavedParts(int slot) const
{
    QStringList parts;
    if (!isModified(slot))
        return parts;
    const Profile p = currentProfile(slot);
    const Profile &saved = m_slots[slot].saved;
    QStringList fields;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        if (p.device.field(i) != saved.device.field(i))
            fields << QString::fromLatin1(deviceFieldName(i));
    }
    if (p.host.v_max != saved.host.v_max)
        fields << u"v_max"_s;
    if (p.host.tau_limit != saved.host.tau_limit)
        fields << u"tau_limit"_s;
    if (p.host.mode != saved.host.mode || p.host.ref_deadzone != saved.host.ref_deadzone)
        fields << tr("the reference settings");
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        if (p.effects.field(i) != saved.effects.field(i))
            fields << QString::fromLatin1(effectFieldName(i));
    }
    if (!fields.isEmpty())
        parts << fields.join(u", "_s);
    if (p.bridge != saved.bridge)
        parts << tr("a bridge setting");
    if (p.notes != saved.notes)
        parts << tr("the notes");
    return parts;
}

bool ProfileController::isModified() const
{
    return isModified(m_active);
}

QString ProfileController::profileName() const
{
    const QString name = m_slots[m_active].saved.name;
    return name.isEmpty() ? tr("Untitled") : name;
}

QString ProfileController::filePath() const
{
    return m_slots[m_active].path;
}

QString ProfileController::windowTitle() const
{
    return profileName() + (isModified() ? u"*"_s : QString()) + u" ["_s + slotName(m_active) +
           u"] — "_s + kAppName;
}

void ProfileController::updateTitle()
{
    const QString title = windowTitle();
    m_saveAction->setEnabled(true);
    if (title != m_title) {
        m_title = title;
        Q_EMIT titleChanged(title);
    }
    Q_EMIT slotsChanged();
}

void ProfileController::load(const Profile &profile, const QString &path, const QString &undoText)
{
    Slot &slot = m_slots[m_active];
    slot.saved = profile;
    slot.path = path;
    m_model->edit(*m_undo, {profile.device, profile.host, profile.effects, profile.passivity},
                  undoText);
    m_bridge = profile.bridge;
    Q_EMIT bridgeSettingsLoaded(m_bridge);
    m_notes = profile.notes;
    Q_EMIT notesChanged(m_notes);
    updateTitle();
}

void ProfileController::setNotes(const QString &notes)
{
    if (notes != m_notes)
        m_undo->push(new NotesEditCommand(this, m_notes, notes));
}

void ProfileController::applyNotes(const QString &notes)
{
    if (notes == m_notes)
        return;
    m_notes = notes;
    Q_EMIT notesChanged(m_notes);
    updateTitle();
}

void ProfileController::setBridgeSettings(const bridge::BridgeSettings &settings)
{
    m_bridge = bridge::withNetworkOf(settings, bridge::BridgeSettings());
    updateTitle();
}

bool ProfileController::openFile(const QString &path, QString *error)
{
    const ProfileReadResult result = readProfile(path);
    if (!result.ok()) {
        const QString text = result.errors.join(u'\n');
        if (error) {
            *error = text;
        } else {
            QMessageBox::warning(
                m_dialogParent, tr("Cannot open profile"),
                tr("%1 was not loaded:\n\n%2").arg(QDir::toNativeSeparators(path), text));
        }
        Q_EMIT statusMessage(
            tr("Cannot open %1: %2").arg(QFileInfo(path).fileName(), result.errors.value(0)));
        if (!QFileInfo::exists(path)) {
            QSettings settings;
            QStringList recent = settings.value(settingsKey(kRecentKey)).toStringList();
            if (recent.removeAll(QFileInfo(path).absoluteFilePath()) > 0) {
                settings.setValue(settingsKey(kRecentKey), recent);
                rebuildRecentMenu();
            }
        }
        return false;
    }
    Profile profile = *result.profile;
    if (profile.name.isEmpty())
        profile.name = QFileInfo(path).completeBaseName();
    load(profile, QFileInfo(path).absoluteFilePath(), tr("Open %1").arg(profile.name));
    addRecent(path);
    QSettings().setValue(settingsKey(kLastDirKey), QFileInfo(path).absolutePath());
    QString message = tr("Opened %1 into slot %2").arg(profile.name, slotName(m_active));
    if (!result.warnings.isEmpty())
        message += u" ("_s + result.warnings.join(u"; "_s) + u')';
    Q_EMIT statusMessage(message);
    return true;
}

bool ProfileController::saveSlot(int slot, const QString &path, QString *error)
{
    Profile profile = currentProfile(slot);
    QStringList problems;
    for (const auto &v : validate(profile.device))
        problems << QString::fromStdString(v.message());
    for (const auto &v : validate(profile.host))
        problems << QString::fromStdString(v.message());
    for (const auto &v : validate(profile.effects, profile.host.tau_limit))
        problems << QString::fromStdString(v.message());
    if (!problems.isEmpty()) {
        const QString text = tr("The parameters are not valid, so they were not saved:\n%1")
                                 .arg(problems.join(u'\n'));
        if (error)
            *error = text;
        return false;
    }
    if (profile.name.isEmpty() || profile.name == kUntitled)
        profile.name = QFileInfo(path).completeBaseName();
    const QString failure = writeProfile(profile, path);
    if (!failure.isEmpty()) {
        if (error)
            *error = failure;
        return false;
    }
    Slot &s = m_slots[slot];
    s.saved = profile;
    s.path = QFileInfo(path).absoluteFilePath();
    if (slot != m_active)
        s.working = profile;
    addRecent(path);
    QSettings().setValue(settingsKey(kLastDirKey), QFileInfo(path).absolutePath());
    updateTitle();
    Q_EMIT statusMessage(tr("Saved %1 to %2").arg(profile.name, QDir::toNativeSeparators(path)));
    return true;
}

bool ProfileController::saveTo(const QString &path, QString *error)
{
    return saveSlot(m_active, path, error);
}

bool ProfileController::saveSlotInteractive(int slot, bool askPath)
{
    QString path = m_slots[slot].path;
    if (askPath || path.isEmpty()) {
        QSettings settings;
        const QString dir =
            path.isEmpty() ? settings.value(settingsKey(kLastDirKey)).toString() : path;
        path = QFileDialog::getSaveFileName(m_dialogParent,
                                            tr("Save profile %1 as").arg(slotName(slot)), dir,
                                            tr("HATPIC profiles (*.json);;All files (*)"));
        if (path.isEmpty())
            return false;
        if (QFileInfo(path).suffix().isEmpty())
            path += u".json"_s;
    }
    QString error;
    if (saveSlot(slot, path, &error))
        return true;
    QMessageBox::warning(m_dialogParent, tr("Cannot save profile"), error);
    Q_EMIT statusMessage(error);
    return false;
}

bool ProfileController::save()
{
    return saveSlotInteractive(m_active, false);
}

bool ProfileController::saveAs()
{
    return saveSlotInteractive(m_active, true);
}

bool ProfileController::loadPreset(const QString &name)
{
    const std::optional<Profile> profile = preset(name);
    if (!profile) {
        Q_EMIT statusMessage(tr("No built-in preset named %1").arg(name));
        return false;
    }
    load(*profile, QString(), tr("Load preset %1").arg(profile->name));
    Q_EMIT statusMessage(
        tr("Loaded preset %1 into slot %2").arg(profile->name, slotName(m_active)));
    return true;
}

bool ProfileController::maybeSaveSlot(int slot)
{
    if (!isModified(slot))
        return true;
    // What is unsaved, by name (issue 27: a changed bridge setting asked to save a profile
    // whose parameters had not changed, without saying why).
    const QString text =
        tr("Profile \"%1\" (slot %2) has unsaved changes: %3. Save them?")
            .arg(m_slots[slot].saved.name.isEmpty() ? tr("Untitled") : m_slots[slot].saved.name,
                 slotName(slot), unsavedParts(slot).join(u"; "_s));
    switch (m_question(text)) {
    case QMessageBox::Save:
        return saveSlotInteractive(slot, false);
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

bool ProfileController::maybeSave()
{
    const int order[] = {m_active, 1 - m_active};
    for (int slot : order) {
        if (!maybeSaveSlot(slot))
            return false;
    }
    return true;
}

void ProfileController::toggleSlot()
{
    const int to = 1 - m_active;
    if (!m_slots[to].used) {
        Slot &b = m_slots[to];
        b.saved = currentProfile(m_active);
        // "(copy)", not "(B)": the title names the slot already (issue 27: "[B]" twice).
        b.saved.name = tr("%1 (copy)").arg(profileName());
        b.working = b.saved;
        b.path.clear();
        b.used = true;
        Q_EMIT statusMessage(tr("Slot %1 starts as a copy of %2: edit it, then switch with Ctrl+B")
                                 .arg(slotName(to), slotName(m_active)));
    }
    m_undo->push(new AbSwitchCommand(this, m_active, to));
}

bool ProfileController::isSlotUsed(int slot) const
{
    return slot >= 0 && slot < kSlotCount && m_slots[slot].used;
}

void ProfileController::activateSlot(int slot, bool pushOnSwitch)
{
    if (slot == m_active || slot < 0 || slot >= kSlotCount)
        return;
    Slot &from = m_slots[m_active];
    from.working = currentProfile(m_active);
    m_active = slot;
    const Slot &to = m_slots[slot];
    // Not an undo step: the A/B switch is one of its own (AbSwitchCommand).
    m_model->setEdited(
        {to.working.device, to.working.host, to.working.effects, to.working.passivity});
    m_bridge = to.working.bridge;
    Q_EMIT bridgeSettingsLoaded(m_bridge);
    m_notes = to.working.notes;
    Q_EMIT notesChanged(m_notes);
    updateTitle();
    Q_EMIT activeSlotChanged(slot);
    Q_EMIT statusMessage(tr("Slot %1: %2").arg(slotName(slot), profileName()));
    if (pushOnSwitch && m_pushOnSwitchAction->isChecked()) {
        if (!m_model->push())
            Q_EMIT statusMessage(
                tr("Slot %1 not pushed on switch: %2").arg(slotName(slot), m_model->syncText()));
    }
}

QStringList ProfileController::recentFiles() const
{
    return QSettings().value(settingsKey(kRecentKey)).toStringList();
}

void ProfileController::addRecent(const QString &path)
{
    QSettings settings;
    QStringList recent = settings.value(settingsKey(kRecentKey)).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kMaxRecentFiles)
        recent.removeLast();
    settings.setValue(settingsKey(kRecentKey), recent);
    rebuildRecentMenu();
}

namespace {

// Removes a menu's actions without deleting them on the spot: the action being triggered
// may be one of them (opening a recent file reorders the list).
void clearLater(QMenu *menu)
{
    for (QAction *a : menu->actions()) {
        menu->removeAction(a);
        if (a->parent() == menu)
            a->deleteLater();
    }
}

} // namespace

void ProfileController::rebuildRecentMenu()
{
    clearLater(m_recentMenu.get());
    const QStringList recent = recentFiles();
    for (int i = 0; i < recent.size(); ++i) {
        const QString path = recent[i];
        QAction *a = m_recentMenu->addAction(u"&"_s + QString::number(i + 1) + u"  "_s +
                                             QFileInfo(path).fileName());
        a->setToolTip(QDir::toNativeSeparators(path));
        a->setStatusTip(QDir::toNativeSeparators(path));
        a->setData(path);
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybeSaveSlot(m_active))
                openFile(path);
        });
    }
    if (recent.isEmpty()) {
        m_recentMenu->addAction(tr("(no recent profiles)"))->setEnabled(false);
        return;
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("Clear list")), &QAction::triggered, this, [this] {
        QSettings().remove(settingsKey(kRecentKey));
        rebuildRecentMenu();
    });
}

QString ProfileController::presetSummary(const QString &notes)
{
    static constexpr qsizetype kMaxChars = 64;
    qsizetype end = notes.size();
    for (const QChar stop : {u'.', u':', u';'}) {
        const qsizetype at = notes.indexOf(stop);
        if (at > 0)
            end = std::min(end, at);
    }
    QString summary = notes.left(end).trimmed();
    if (summary.size() > kMaxChars)
        summary = summary.left(kMaxChars - 1).trimmed() + u'…';
    return summary;
}

void ProfileController::rebuildPresetsMenu()
{
    clearLater(m_presetsMenu.get());
    for (const QString &name : presetNames()) {
        QAction *a = m_presetsMenu->addAction(name);
        a->setData(name);
        if (const auto p = preset(name)) {
            // What it is, in the menu itself (issue 27: only a tooltip said it, unseen): the
            // notes' first clause; all of them in the tooltip.
            const QString summary = presetSummary(p->notes);
            if (!summary.isEmpty())
                a->setText(name + u" — "_s + summary);
            a->setToolTip(p->notes);
            a->setStatusTip(p->notes);
        }
        connect(a, &QAction::triggered, this, [this, name] {
            if (maybeSaveSlot(m_active))
                loadPreset(name);
        });
    }
    m_presetsMenu->setToolTipsVisible(true);
}

} // namespace hatpic
