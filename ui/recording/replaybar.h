// The replay strip shown above the plots in replay mode: what is replayed, play/pause, speed,
// a scrub slider, the playhead time, a second recording to overlay (and where it is aligned),
// and one button back to live.
#pragma once

#include <QFrame>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QToolButton;

namespace hatpic {

class ReplayController;

class ReplayBar : public QFrame
{
    Q_OBJECT
public:
    //! One slider step per millisecond while the recording is short enough…
    static constexpr int kSliderStepsPerSecond = 1000;
    //! …and never more steps than this: a longer recording is cut into this many equal steps,
    //! so that any finite span fits the slider's int.
    static constexpr int kMaxSliderSteps = 10'000'000;

    //! Seconds as the bar writes them: fixed with `decimals` up to a million, then in
    //! scientific notation, so the text stays short for any finite value.
    static QString compactSeconds(double seconds, int decimals = 2);

    explicit ReplayBar(ReplayController *controller, QWidget *parent = nullptr);

    QSlider *slider() const { return m_slider; }
    QComboBox *speedBox() const { return m_speed; }
    QPushButton *liveButton() const { return m_live; }
    QToolButton *overlayButton() const { return m_overlayOpen; }
    QComboBox *overlayAlignBox() const { return m_overlayAlign; }
    QToolButton *playButton() const { return m_play; }
    QString positionText() const;
    //! The playhead `t` in session time, as the plots' time axis shows it: "t = 103.00 s".
    static QString sessionTimeText(double t);
    //! The playhead time of slider value `value`, and the value nearest time `t` [s].
    double timeOfSliderValue(int value) const;
    int sliderValueOf(double t) const;

Q_SIGNALS:
    void backToLiveRequested();
    //! The person asked to overlay a second recording (the window asks which).
    void overlayRequested();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void elideTitle();
    void onActiveChanged(bool active);
    void onPositionChanged(double t);
    void onPlayingChanged(bool playing);
    void onOverlayChanged();

    ReplayController *m_controller;
    QLabel *m_title = nullptr;
    QString m_titleText; //!< in full; the label shows it elided when the bar is narrow
    QToolButton *m_play = nullptr;
    QComboBox *m_speed = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_time = nullptr;
    QLabel *m_sessionTime = nullptr;
    bool m_millisecondSteps = true; //!< the slider counts milliseconds (else equal fractions)
    QPushButton *m_live = nullptr;
    QToolButton *m_overlayOpen = nullptr;
    QLabel *m_overlayTitle = nullptr;
    QComboBox *m_overlayAlign = nullptr;
    QToolButton *m_overlayClose = nullptr;
};

} // namespace hatpic
