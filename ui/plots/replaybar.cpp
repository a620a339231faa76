#include "plots/replaybar.h"

#include "plots/replaycontroller.h"

#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace hatpic {

ReplayBar::ReplayBar(ReplayController *controller, QWidget *parent)
    : QFrame(parent), m_controller(controller)
{
    setObjectName(QStringLiteral("replayBar"));
    setStyleSheet(QStringLiteral("#replayBar { background: #1565c0; border-radius: 4px; }"
                                 "#replayBar QLabel { color: white; }"));
    auto *tag = new QLabel(tr("REPLAY"), this);
    tag->setStyleSheet(QStringLiteral("font-weight: bold; padding: 0 6px;"));
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("replayTitle"));
    // The title gives way in a narrow window (elided, in full in its tooltip) so that the
    // slider keeps a usable length and the bar does not widen the window's centre.
    m_title->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_title->setMinimumWidth(m_title->fontMetrics().horizontalAdvance(QStringLiteral("hatpic…")));
    m_title->installEventFilter(this);

    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("replayPlay"));
    m_play->setAutoRaise(false);
    connect(m_play, &QToolButton::clicked, controller, &ReplayController::togglePlay);

    m_speed = new QComboBox(this);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    for (int speed : {1, 2, 5})
        m_speed->addItem(QStringLiteral("%1×").arg(speed), double(speed));
    m_speed->setToolTip(tr("Playback speed"));
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this] { m_controller->setSpeed(m_speed->currentData().toDouble()); });

    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("replaySlider"));
    m_slider->setToolTip(tr("Drag to scrub through the recording"));
    m_slider->setMinimumWidth(120);
    connect(m_slider, &QSlider::valueChanged, this, [this](int value) {
        m_controller->setPosition(m_controller->startTime() +
                                  double(value) / kSliderStepsPerSecond);
    });

    m_time = new QLabel(this);
    m_time->setObjectName(QStringLiteral("replayTime"));

    m_live = new QPushButton(tr("Back to &live"), this);
    m_live->setObjectName(QStringLiteral("backToLive"));
    m_live->setToolTip(tr("Leave the replay and show the live data again"));
    connect(m_live, &QPushButton::clicked, this, &ReplayBar::backToLiveRequested);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(tag);
    layout->addWidget(m_title, 1);
    layout->addWidget(m_play);
    layout->addWidget(m_speed);
    layout->addWidget(m_slider, 2);
    layout->addWidget(m_time);
    layout->addWidget(m_live);

    connect(controller, &ReplayController::activeChanged, this, &ReplayBar::onActiveChanged);
    connect(controller, &ReplayController::positionChanged, this, &ReplayBar::onPositionChanged);
    connect(controller, &ReplayController::playingChanged, this, &ReplayBar::onPlayingChanged);
    onPlayingChanged(false);
    onActiveChanged(controller->isActive());
}

void ReplayBar::onActiveChanged(bool active)
{
    setVisible(active);
    if (!active)
        return;
    const Recording &rec = m_controller->recording();
    QString title = QFileInfo(m_controller->path()).fileName();
    if (rec.hasMetadata && !rec.metadata.source.isEmpty())
        title += tr(" — from %1").arg(rec.metadata.source);
    if (rec.hasMetadata && rec.metadata.start.isValid())
        title += tr(", %1").arg(
            rec.metadata.start.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    m_titleText = title;
    m_title->setToolTip(m_controller->path() % u'\n' % title);
    elideTitle();
    const QSignalBlocker blocker(m_slider);
    const double length = m_controller->endTime() - m_controller->startTime();
    m_slider->setRange(0, static_cast<int>(std::ceil(length * kSliderStepsPerSecond)));
    m_slider->setPageStep(kSliderStepsPerSecond);
    // Wide enough for the longest position text of this recording, so it does not jitter.
    const QString longest = tr("%1 / %1 s").arg(length, 0, 'f', 2);
    m_time->setMinimumWidth(m_time->fontMetrics().horizontalAdvance(longest) + 4);
    onPositionChanged(m_controller->position());
}

void ReplayBar::elideTitle()
{
    m_title->setText(m_title->fontMetrics().elidedText(m_titleText, Qt::ElideRight,
                                                       m_title->contentsRect().width()));
}

bool ReplayBar::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_title && event->type() == QEvent::Resize)
        elideTitle();
    return QFrame::eventFilter(watched, event);
}

void ReplayBar::onPositionChanged(double t)
{
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setValue(
            static_cast<int>(std::lround((t - m_controller->startTime()) * kSliderStepsPerSecond)));
    }
    m_time->setText(positionText());
}

void ReplayBar::onPlayingChanged(bool playing)
{
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setToolTip(playing ? tr("Pause the replay") : tr("Play the replay"));
}

QString ReplayBar::positionText() const
{
    return tr("%1 / %2 s")
        .arg(m_controller->position() - m_controller->startTime(), 0, 'f', 2)
        .arg(m_controller->endTime() - m_controller->startTime(), 0, 'f', 2);
}

} // namespace hatpic
