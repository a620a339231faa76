#include "editor/syncbar.h"

#include "editor/undobutton.h"
#include "plots/palette.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QToolButton *actionButton(QAction *action, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return button;
}

QString stateColour(SyncState state)
{
    switch (state) {
    case SyncState::InSync:
        return u"#2e7d32"_s;
    case SyncState::Edited:
        return u"#ef6c00"_s;
    case SyncState::Pushing:
    case SyncState::AwaitingReadback:
        return u"#1565c0"_s;
    case SyncState::ReadbackDiffers:
    case SyncState::Rejected:
    case SyncState::Timeout:
    case SyncState::Failed:
        return palette::kProblemText.name();
    case SyncState::NotConnected:
    case SyncState::NotRead:
        break;
    }
    return u"#757575"_s;
}

} // namespace

SyncBar::SyncBar(QUndoStack *undo, QAction *read, QAction *revert, QAction *push, QWidget *parent)
    : QWidget(parent)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);

    m_label = new QLabel(this);
    m_label->setObjectName(u"sync_state"_s);
    m_label->setWordWrap(true);
    m_label->setToolTip(tr("Whether the device renders what the editor shows"));
    grid->addWidget(m_label, 0, 0);

    auto *buttons = new QHBoxLayout;
    buttons->setSpacing(4);
    buttons->addWidget(new UndoButton(undo, UndoButton::Direction::Undo, this));
    buttons->addWidget(new UndoButton(undo, UndoButton::Direction::Redo, this));
    buttons->addSpacing(8);
    buttons->addWidget(actionButton(read, this));
    buttons->addWidget(actionButton(revert, this));
    auto *pushButton = actionButton(push, this);
    pushButton->setObjectName(u"button_push"_s);
    pushButton->setStyleSheet(QStringLiteral("QToolButton:enabled { font-weight: bold; }"));
    buttons->addWidget(pushButton);
    grid->addLayout(buttons, 0, 1, Qt::AlignRight);

    // Push is off while a rule is broken: the reason sits here, next to it, whatever the
    // panel's scroll position (the field's own message may be below the fold).
    m_problem = new QLabel(this);
    m_problem->setObjectName(u"push_problem"_s);
    m_problem->setWordWrap(true);
    m_problem->setTextFormat(Qt::RichText);
    m_problem->hide();
    connect(m_problem, &QLabel::linkActivated, this, &SyncBar::showProblemRequested);
    grid->addWidget(m_problem, 1, 0, 1, 2);

    auto *options = new QHBoxLayout;
    // A device with several knobs keeps a tuning per knob: the one edited, pushed and read.
    m_knobLabel = new QLabel(tr("Tune knob"), this);
    m_knobBox = new QComboBox(this);
    m_knobBox->setObjectName(u"combo_knob"_s);
    m_knobBox->setToolTip(tr("The knob whose tuning Push, Read, ZERO and the vibration test "
                             "reach; the others keep theirs"));
    m_knobLabel->setBuddy(m_knobBox);
    connect(m_knobBox, &QComboBox::activated, this, &SyncBar::knobSelected);
    options->addWidget(m_knobLabel);
    options->addWidget(m_knobBox);
    options->addSpacing(8);
    setKnobs(1);
    m_liveCheck = new QCheckBox(tr("Live push while editing"), this);
    m_liveCheck->setObjectName(u"check_live_push"_s);
    m_liveCheck->setToolTip(tr("Push every change as you drag or type (at most 10 pushes per "
                               "second, one at a time; the last value is always sent)"));
    connect(m_liveCheck, &QCheckBox::toggled, this, &SyncBar::livePushToggled);
    m_degreesCheck = new QCheckBox(tr("Angles in degrees"), this);
    m_degreesCheck->setObjectName(u"check_degrees"_s);
    m_degreesCheck->setToolTip(tr("Show θ0, N and Q_dz in degrees; files and the device stay "
                                  "in radians"));
    connect(m_degreesCheck, &QCheckBox::toggled, this, &SyncBar::angleInDegreesToggled);
    options->addWidget(m_liveCheck);
    options->addWidget(m_degreesCheck);
    options->addStretch(1);
    grid->addLayout(options, 2, 0, 1, 2);
    grid->setColumnStretch(0, 1);
    // Only the fields are Tab stops; the buttons have shortcuts (Ctrl+Return, Ctrl+Shift+R, …).
    // A click on a button leaves the focus where it was (issue 27: Push took it, and handed it
    // on to the simulated hand's selector once disabled while pushing); a check box takes it.
    for (QWidget *w : findChildren<QWidget *>()) {
        if (qobject_cast<QToolButton *>(w))
            w->setFocusPolicy(Qt::NoFocus);
        else if (w->focusPolicy() & Qt::TabFocus)
            w->setFocusPolicy(Qt::ClickFocus);
    }
}

void SyncBar::setState(SyncState state, const QString &text)
{
    m_label->setText(u"<span style=\"color:"_s + stateColour(state) + u"\">●</span> <b>"_s +
                     text.toHtmlEscaped() + u"</b>"_s);
}

void SyncBar::setProblems(const QStringList &problems)
{
    m_problem->setVisible(!problems.isEmpty());
    if (problems.isEmpty()) {
        m_problem->clear();
        m_problem->setToolTip({});
        return;
    }
    const QString more =
        problems.size() > 1 ? tr(" (and %1 more)").arg(problems.size() - 1) : QString();
    m_problem->setText(u"<span style=\"color:"_s + palette::kProblemText.name() + u"\">"_s +
                       tr("Cannot push: %1%2").arg(problems.first(), more).toHtmlEscaped() +
                       u"</span> <a href=\"show\">"_s + tr("Show") + u"</a>"_s);
    m_problem->setToolTip(problems.join(u'\n'));
}

void SyncBar::setLivePush(bool on)
{
    const QSignalBlocker block(m_liveCheck);
    m_liveCheck->setChecked(on);
}

void SyncBar::setKnobs(int count)
{
    const QSignalBlocker block(m_knobBox);
    m_knobBox->clear();
    for (int k = 1; k <= count; ++k)
        m_knobBox->addItem(tr("Knob %1").arg(k));
    m_knobLabel->setVisible(count > 1);
    m_knobBox->setVisible(count > 1);
}

int SyncBar::knob() const
{
    return std::max(0, m_knobBox->currentIndex());
}

void SyncBar::setAngleInDegrees(bool on)
{
    const QSignalBlocker block(m_degreesCheck);
    m_degreesCheck->setChecked(on);
}

} // namespace hatpic
