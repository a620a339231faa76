#include "recording/replaybar.h"

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

#include <algorithm>
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
    connect(m_slider, &QSlider::valueChanged, this,
            [this](int value) { m_controller->setPosition(timeOfSliderValue(value)); });

    // Two time bases, each labelled: the playhead into the recording (what the slider spans)
    // and the session time the plots' time axis counts.
    m_time = new QLabel(this);
    m_time->setObjectName(QStringLiteral("replayTime"));
    m_time->setToolTip(tr("Playhead into the recording / the recording's length"));
    m_sessionTime = new QLabel(this);
    m_sessionTime->setObjectName(QStringLiteral("replaySessionTime"));
    m_sessionTime->setToolTip(
        tr("Playhead in session time: the time axis of the plots and the cursor's t"));
    m_sessionTime->setMinimumWidth(1); // gives way first in a narrow window

    m_live = new QPushButton(tr("Back to &live"), this);
    m_live->setObjectName(QStringLiteral("backToLive"));
    m_live->setToolTip(tr("Leave the replay and show the live data again"));
    connect(m_live, &QPushButton::clicked, this, &ReplayBar::backToLiveRequested);

    m_overlayOpen = new QToolButton(this);
    m_overlayOpen->setObjectName(QStringLiteral("overlayOpen"));
    // Compact ("+"), so that the strip keeps its minimum width; the tooltip says what it does.
    m_overlayOpen->setText(tr("+"));
    m_overlayOpen->setToolTip(tr("Overlay a second recording: drawn fainter on the same plots"));
    connect(m_overlayOpen, &QToolButton::clicked, this, &ReplayBar::overlayRequested);
    m_overlayTitle = new QLabel(this);
    m_overlayTitle->setObjectName(QStringLiteral("overlayTitle"));
    m_overlayTitle->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // gives way
    m_overlayAlign = new QComboBox(this);
    m_overlayAlign->setObjectName(QStringLiteral("overlayAlign"));
    m_overlayAlign->addItem(tr("aligned at the trigger"), int(ReplayController::Align::Trigger));
    m_overlayAlign->addItem(tr("aligned at the start"), int(ReplayController::Align::Start));
    m_overlayAlign->setToolTip(
        tr("Trigger: the first trigger or other event of each recording; start: their first "
           "samples"));
    connect(m_overlayAlign, &QComboBox::currentIndexChanged, this, [this] {
        m_controller->setOverlayAlign(
            static_cast<ReplayController::Align>(m_overlayAlign->currentData().toInt()));
    });
    m_overlayClose = new QToolButton(this);
    m_overlayClose->setObjectName(QStringLiteral("overlayClose"));
    m_overlayClose->setText(QStringLiteral("✕"));
    m_overlayClose->setToolTip(tr("Remove the overlay"));
    connect(m_overlayClose, &QToolButton::clicked, controller, &ReplayController::closeOverlay);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(tag);
    layout->addWidget(m_title, 1);
    layout->addWidget(m_play);
    layout->addWidget(m_speed);
    layout->addWidget(m_slider, 2);
    layout->addWidget(m_time);
    layout->addWidget(m_sessionTime);
    layout->addWidget(m_overlayOpen);
    layout->addWidget(m_overlayTitle);
    layout->addWidget(m_overlayAlign);
    layout->addWidget(m_overlayClose);
    layout->addWidget(m_live);

    connect(controller, &ReplayController::activeChanged, this, &ReplayBar::onActiveChanged);
    connect(controller, &ReplayController::positionChanged, this, &ReplayBar::onPositionChanged);
    connect(controller, &ReplayController::playingChanged, this, &ReplayBar::onPlayingChanged);
    connect(controller, &ReplayController::overlayChanged, this, &ReplayBar::onOverlayChanged);
    onOverlayChanged();
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
    // Any finite span: up to kMaxSliderSteps milliseconds, one step per millisecond; beyond,
    // kMaxSliderSteps equal steps (the span itself may even exceed the largest double).
    const double length = m_controller->endTime() - m_controller->startTime();
    m_millisecondSteps = length * kSliderStepsPerSecond <= kMaxSliderSteps;
    const int steps = m_millisecondSteps
                          ? static_cast<int>(std::ceil(length * kSliderStepsPerSecond))
                          : kMaxSliderSteps;
    m_slider->setRange(0, steps);
    m_slider->setPageStep(m_millisecondSteps ? kSliderStepsPerSecond
                                             : std::max(1, kMaxSliderSteps / 100));
    // Wide enough for the longest position text of this recording, so it does not jitter;
    // compactSeconds() keeps that bounded for any span.
    const QString longest = tr("%1 / %1 s").arg(compactSeconds(length));
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
        m_slider->setValue(sliderValueOf(t));
    }
    m_time->setText(positionText());
    m_sessionTime->setText(sessionTimeText(t));
}

void ReplayBar::onPlayingChanged(bool playing)
{
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setToolTip(playing ? tr("Pause the replay") : tr("Play the replay"));
}

void ReplayBar::onOverlayChanged()
{
    const bool has = m_controller->hasOverlay();
    m_overlayTitle->setVisible(has);
    m_overlayAlign->setVisible(has);
    m_overlayClose->setVisible(has);
    if (!has)
        return;
    m_overlayTitle->setText(tr("+ %1").arg(QFileInfo(m_controller->overlayPath()).fileName()));
    m_overlayTitle->setToolTip(
        tr("%1, drawn fainter, moved by %2 s")
            .arg(m_controller->overlayPath(), compactSeconds(m_controller->overlayOffset(), 3)));
    const QSignalBlocker blocker(m_overlayAlign);
    m_overlayAlign->setCurrentIndex(m_overlayAlign->findData(int(m_controller->overlayAlign())));
}

QString ReplayBar::positionText() const
{
    return tr("%1 / %2 s")
        .arg(compactSeconds(m_controller->position() - m_controller->startTime()),
             compactSeconds(m_controller->endTime() - m_controller->startTime()));
}

QString ReplayBar::sessionTimeText(double t)
{
    return tr("t = %1 s").arg(compactSeconds(t));
}

QString ReplayBar::compactSeconds(double seconds, int decimals)
{
    if (std::isnan(seconds))
        return QStringLiteral("—");
    if (std::isinf(seconds)) // a span beyond the largest double
        return seconds > 0 ? QStringLiteral("> 1.8e+308") : QStringLiteral("< −1.8e+308");
    if (std::abs(seconds) < 1e6)
        return QString::number(seconds, 'f', decimals);
    return QString::number(seconds, 'e', 3);
}

double ReplayBar::timeOfSliderValue(int value) const
{
    const double start = m_controller->startTime();
    const double end = m_controller->endTime();
    if (m_millisecondSteps)
        return std::min(start + double(value) / kSliderStepsPerSecond, end);
    // A weighted mean never overflows, even when end − start does.
    const double f = std::clamp(double(value) / kMaxSliderSteps, 0.0, 1.0);
    return start * (1 - f) + end * f;
}

int ReplayBar::sliderValueOf(double t) const
{
    const double start = m_controller->startTime();
    const double end = m_controller->endTime();
    double steps = 0;
    if (m_millisecondSteps) {
        steps = (t - start) * kSliderStepsPerSecond;
    } else {
        // Halves, so that neither difference overflows.
        const double half = end / 2 - start / 2;
        steps = half > 0 ? (t / 2 - start / 2) / half * kMaxSliderSteps : 0;
    }
    if (!std::isfinite(steps))
        return 0;
    return static_cast<int>(
        std::lround(std::clamp(steps, 0.0, double(std::max(m_slider->maximum(), 0)))));
}

} // namespace hatpic
