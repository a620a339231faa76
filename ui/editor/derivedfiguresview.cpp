#include "editor/derivedfiguresview.h"

#include "plots/palette.h"
#include "plots/plottheme.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QResizeEvent>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

constexpr double kWarningTint = 0.15; //!< share of kWarningFrame in a warning's background

QString num(double v, int digits = 3)
{
    if (std::isinf(v))
        return QStringLiteral("∞");
    return QString::number(v, 'g', digits);
}

QLabel *valueLabel(QWidget *parent, const QString &name, const QString &tip)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setToolTip(tip);
    return label;
}

QLabel *warningLabel(QWidget *parent, const QString &name)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->hide();
    return label;
}

//! Lines of warning text kept in sight at least: two warnings at the editor's usual width.
constexpr int kWarningLines = 8;

//! The warnings' own scroll area: as tall as its wrapped text wants at its width; more than
//! kWarningLines (three warnings, a narrow editor) scroll, so the figures above are never cut
//! (issue 27).
class WarningsScroll : public QScrollArea
{
public:
    explicit WarningsScroll(QWidget *parent) : QScrollArea(parent)
    {
        setWidgetResizable(true);
        setFrameShape(QFrame::NoFrame);
        setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    }

    QSize sizeHint() const override
    {
        if (!widget())
            return QScrollArea::sizeHint();
        const int width = std::max(viewport()->width(), 100);
        return {QScrollArea::sizeHint().width(), widget()->heightForWidth(width)};
    }

    QSize minimumSizeHint() const override
    {
        return {QScrollArea::minimumSizeHint().width(),
                std::min(sizeHint().height(), kWarningLines * fontMetrics().height())};
    }

protected:
    void resizeEvent(QResizeEvent *event) override
    {
        QScrollArea::resizeEvent(event);
        if (event->size().width() != event->oldSize().width())
            updateGeometry(); // the wrapped text's height follows the width
    }
};

} // namespace

DerivedFiguresView::DerivedFiguresView(QWidget *parent) : QWidget(parent)
{
    // The figures at their full height always; the warnings below take what is left.
    auto *figures = new QWidget(this);
    figures->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    auto *form = new QGridLayout(figures);
    form->setContentsMargins(0, 0, 0, 0);

    m_omega = valueLabel(this, u"figure_omega_n"_s,
                         tr("Natural frequency √(K_max / D_adm) of the admittance filter with the "
                            "notch stiffness: how fast the knob springs back."));
    m_zeta = valueLabel(this, u"figure_zeta"_s,
                        tr("Damping ratio M_adm / (2·√(K_max·D_adm)). Below 0.3 the knob "
                           "overshoots and rings when released."));
    m_timeConstant = valueLabel(this, u"figure_time_constant"_s,
                                tr("Time constant D_adm / M_adm of the admittance filter: how "
                                   "quickly the knob's velocity follows a torque."));
    m_peak = valueLabel(this, u"figure_peak_tau"_s,
                        tr("Largest |τ_rec| over |θ−θ0| ≤ π/2, compared with the actuator's "
                           "torque limit tau_limit."));
    m_peakBar = new QProgressBar(this);
    m_peakBar->setObjectName(u"figure_peak_bar"_s);
    m_peakBar->setRange(0, 100);
    // The percentage beside the bar, not in it: drawn in the bar it straddled the chunk's edge,
    // half in one colour, half in another.
    m_peakBar->setTextVisible(false);
    m_peakBar->setMaximumHeight(14);
    m_peakBar->setToolTip(m_peak->toolTip());
    m_peakPercent = valueLabel(this, u"figure_peak_percent"_s, m_peak->toolTip());

    // Two figures a row: the box sits next to Push, above the scrolling fields, and must stay
    // in sight at 1280×720.
    auto pair = [&](int row, int column, const QString &name, QWidget *value, int span = 1) {
        auto *label = new QLabel(name, this);
        label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        // Quieter than the figures, in either theme: the palette's secondary text.
        label->setForegroundRole(QPalette::PlaceholderText);
        form->addWidget(label, row, 2 * column);
        form->addWidget(value, row, 2 * column + 1, 1, span);
    };
    pair(0, 0, tr("ω_n"), m_omega);
    pair(0, 1, tr("ζ"), m_zeta);
    pair(1, 0, tr("D_adm/M_adm"), m_timeConstant, 3);
    pair(2, 0, tr("peak |τ_rec|"), m_peak, 3);
    form->addWidget(m_peakBar, 3, 1, 1, 2);
    form->addWidget(m_peakPercent, 3, 3);
    form->setColumnStretch(1, 1);
    form->setColumnStretch(3, 1);
    form->setVerticalSpacing(2);

    auto *warnings = new QWidget;
    m_saturation = warningLabel(warnings, u"warning_saturation"_s);
    m_ringing = warningLabel(warnings, u"warning_ringing"_s);
    m_chatter = warningLabel(warnings, u"warning_chatter"_s);
    auto *warningLayout = new QVBoxLayout(warnings);
    warningLayout->setContentsMargins(0, 0, 0, 0);
    warningLayout->addWidget(m_saturation);
    warningLayout->addWidget(m_ringing);
    warningLayout->addWidget(m_chatter);
    m_warnings = new WarningsScroll(this);
    m_warnings->setObjectName(u"derivedWarnings"_s);
    m_warnings->setWidget(warnings);
    // On the box's own background, as the warnings were before they could scroll.
    warnings->setAutoFillBackground(false);
    m_warnings->viewport()->setAutoFillBackground(false);
    m_warnings->hide();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(figures);
    layout->addWidget(m_warnings);
    applyPalette();
    refresh();
}

void DerivedFiguresView::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyPalette();
}

void DerivedFiguresView::applyPalette()
{
    // The warnings: the window's text on the window's colour tinted with their frame's orange,
    // framed in it, so they stand out and read alike on the light and the dark theme.
    const QPalette &p = palette();
    const QString style =
        QStringLiteral("QLabel { background: %1; color: %2; border: 1px solid %3;"
                       " border-radius: 4px; padding: 4px; }")
            .arg(plottheme::mix(palette::kWarningFrame, p.color(QPalette::Window), kWarningTint)
                     .name(),
                 p.color(QPalette::WindowText).name(), palette::kWarningFrame.name());
    for (QLabel *warning : {m_saturation, m_ringing, m_chatter})
        warning->setStyleSheet(style);
}

void DerivedFiguresView::setFigures(const DerivedFigures &figures, bool valid)
{
    m_figures = figures;
    m_valid = valid;
    refresh();
}

void DerivedFiguresView::setAngleInDegrees(bool degrees)
{
    m_degrees = degrees;
    refresh();
}

bool DerivedFiguresView::isShowingSaturation() const
{
    return !m_saturation->isHidden();
}

bool DerivedFiguresView::isShowingRinging() const
{
    return !m_ringing->isHidden();
}

bool DerivedFiguresView::isShowingChatter() const
{
    return !m_chatter->isHidden();
}

void DerivedFiguresView::setChatter(std::optional<double> frequency, double jump)
{
    m_chatter->setVisible(frequency.has_value());
    if (frequency) {
        m_chatter->setText(tr("⚠ Chatters: the knob crosses the dead-zone edge back and forth "
                              "about %1 times a second. The torque jumps by K_max·Q_dz = %2 N·m "
                              "there, more than the hand holds. Lower K_max or Q_dz.")
                               .arg(num(*frequency, 2), num(jump)));
    }
    showWarnings();
}

void DerivedFiguresView::showWarnings()
{
    m_warnings->setVisible(isShowingSaturation() || isShowingRinging() || isShowingChatter());
    m_warnings->updateGeometry();
}

QString DerivedFiguresView::warningText() const
{
    QStringList lines;
    if (isShowingSaturation())
        lines << m_saturation->text();
    if (isShowingRinging())
        lines << m_ringing->text();
    if (isShowingChatter())
        lines << m_chatter->text();
    return lines.join(u'\n');
}

void DerivedFiguresView::refresh()
{
    const DerivedFigures &f = m_figures;
    if (!m_valid) {
        const QString dash = QStringLiteral("—");
        m_omega->setText(dash);
        m_zeta->setText(dash);
        m_timeConstant->setText(dash);
        m_peak->setText(tr("— (parameters invalid)"));
        m_peakBar->setValue(0);
        m_peakPercent->clear();
        m_saturation->hide();
        m_ringing->hide();
        showWarnings();
        return;
    }

    m_omega->setText(
        tr("%1 rad/s  (%2 Hz)").arg(num(f.omega_n), num(f.omega_n / (2.0 * std::numbers::pi))));
    const QString zeta = num(f.zeta);
    m_zeta->setText(
        f.rings() ? tr("<span style=\"color:%3\"><b>%1</b></span>"
                       "&nbsp;&nbsp;(&lt; %2: rings)")
                        .arg(zeta, num(DerivedFigures::kRingingZeta), palette::kProblemText.name())
                  : zeta);
    m_timeConstant->setText(f.timeConstant < 1.0 ? tr("%1 ms").arg(num(f.timeConstant * 1e3))
                                                 : tr("%1 s").arg(num(f.timeConstant)));

    const QString angle = m_degrees ? tr("%1°").arg(num(f.peakAngle * 180.0 / std::numbers::pi))
                                    : tr("%1 rad").arg(num(f.peakAngle));
    m_peak->setText(tr("%1 N·m at |θ−θ0| = %2   (limit %3 N·m)")
                        .arg(num(f.peakTauRec), angle, num(f.tauLimit)));
    const double ratio = f.tauLimit > 0 ? f.peakTauRec / f.tauLimit : 0.0;
    m_peakBar->setValue(static_cast<int>(std::lround(std::clamp(ratio, 0.0, 1.0) * 100)));
    m_peakPercent->setText(tr("%1 % of tau_limit").arg(std::lround(ratio * 100)));
    // The bar is drawn from the palette (groove Base, chunk Highlight); a saturating peak
    // takes tau_limit's red.
    QPalette bar;
    if (f.saturates())
        bar.setColor(QPalette::Highlight, palette::kLimit);
    m_peakBar->setPalette(bar);

    m_saturation->setVisible(f.saturates());
    if (f.saturates()) {
        m_saturation->setText(tr("⚠ Saturates: the re-centering torque reaches %1 N·m, above the "
                                 "actuator limit of %2 N·m. The device will clip it, so the "
                                 "curve you tune is not what the hand feels there.")
                                  .arg(num(f.peakTauRec), num(f.tauLimit)));
    }
    m_ringing->setVisible(f.rings());
    if (f.rings()) {
        m_ringing->setText(tr("⚠ Rings: ζ = %1 is below %2, so the knob will overshoot and "
                              "oscillate around center when released. Raise M_adm (damping), or "
                              "lower D_adm (inertia) or K_max.")
                               .arg(num(f.zeta), num(DerivedFigures::kRingingZeta)));
    }
    showWarnings();
}

} // namespace hatpic
