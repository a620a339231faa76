#include "editor/parameterfield.h"

#include "editor/scientificspinbox.h"
#include "model/params.h"
#include "plots/palette.h"

#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Slider positions give values rounded to 4 significant digits, so dragging does not produce
// 0.12566370614359174-style numbers in profiles.
double roundSignificant(double value, int digits)
{
    return QString::number(value, 'g', digits).toDouble();
}

const QString kClampStyle = QStringLiteral("color: %1;").arg(palette::kCautionText.name());
const QString kProblemStyle = QStringLiteral("color: %1;").arg(palette::kProblemText.name());

const QString kInvalidStyle = QStringLiteral(
    "QAbstractSpinBox { border: 2px solid #d32f2f; border-radius: 3px; padding: 1px; }");

} // namespace

ParameterField::ParameterField(const Spec &spec, QWidget *parentWidget, QObject *parent)
    : QObject(parent), m_spec(spec)
{
    const QString tip = u"<b>"_s + spec.symbol + u"</b> — "_s + spec.meaning + u" ["_s + spec.unit +
                        u"]<br>"_s + spec.toolTip;

    m_marker = new QLabel(parentWidget);
    m_marker->setObjectName(u"diff_"_s + spec.key);
    m_marker->setText(QStringLiteral("●"));
    m_marker->setStyleSheet(QStringLiteral("color: %1;").arg(palette::kEditedMark.name()));
    QSizePolicy keep = m_marker->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_marker->setSizePolicy(keep);
    m_marker->hide();

    m_label = new QLabel(parentWidget);
    m_label->setObjectName(u"label_"_s + spec.key);
    m_label->setText(u"<b>"_s + spec.symbol + u"</b>&nbsp;&nbsp;<span style=\"color:gray\">"_s +
                     spec.meaning + u"</span>"_s);
    m_label->setToolTip(tip);

    m_spin = new ScientificSpinBox(parentWidget);
    m_spin->setObjectName(u"spin_"_s + spec.key);
    m_spin->setStepMode(spec.relativeStep ? ScientificSpinBox::StepMode::Relative
                                          : ScientificSpinBox::StepMode::Fixed);
    m_spin->setMinimumWidth(m_spin->fontMetrics().horizontalAdvance(u"-0.0000000"_s) + 30);
    m_spin->setToolTip(tip);
    m_label->setBuddy(m_spin);

    m_unit = new QLabel(spec.unit, parentWidget);
    m_unit->setObjectName(u"unit_"_s + spec.key);

    m_slider = new QSlider(Qt::Horizontal, parentWidget);
    m_slider->setObjectName(u"slider_"_s + spec.key);
    m_slider->setRange(0, kSliderTicks);
    m_slider->setMinimumWidth(60);
    m_slider->setFocusPolicy(Qt::ClickFocus); // Tab goes from field to field
    m_slider->setToolTip(tip);

    m_message = new QLabel(parentWidget);
    m_message->setObjectName(u"error_"_s + spec.key);
    m_message->setStyleSheet(kProblemStyle);
    m_message->setWordWrap(true);
    m_message->hide();

    m_value = spec.minimum;
    updateSpinRange();
    setValue(spec.minimum);

    connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double shown) {
        const double v = shown / displayScale();
        if (v == m_value)
            return;
        if (!m_note.isEmpty() && shown != m_spin->minimum() && shown != m_spin->maximum()) {
            m_note.clear();
            updateMessage();
        }
        m_value = v;
        updateSlider();
        updateMarker();
        Q_EMIT edited(v);
    });
    connect(m_spin, &QAbstractSpinBox::editingFinished, this, &ParameterField::editFinished);
    connect(m_spin, &ScientificSpinBox::clamped, this, &ParameterField::showClamp);
    connect(m_spin, &ScientificSpinBox::refused, this, &ParameterField::showRefusal);
    connect(m_spin, &ScientificSpinBox::notANumber, this, &ParameterField::showNotANumber);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        const double v = sliderToValue(position);
        if (v == m_value)
            return;
        m_value = v;
        if (!m_note.isEmpty()) {
            m_note.clear();
            updateMessage();
        }
        {
            const QSignalBlocker block(m_spin);
            m_spin->setValue(v * displayScale());
        }
        updateMarker();
        Q_EMIT edited(v);
    });
    connect(m_slider, &QSlider::sliderReleased, this, &ParameterField::editFinished);
}

void ParameterField::alignColumns(const QList<ParameterField *> &fields,
                                  const QList<QLabel *> &extraNames)
{
    QList<QLabel *> names = extraNames;
    QList<QLabel *> units;
    for (const ParameterField *f : fields) {
        names << f->m_label;
        units << f->m_unit;
    }
    for (const QList<QLabel *> &column : {names, units}) {
        int width = 0;
        for (const QLabel *l : column)
            width = std::max(width, l->sizeHint().width());
        for (QLabel *l : column)
            l->setMinimumWidth(width);
    }
}

QGridLayout *ParameterField::newGrid(QWidget *parent)
{
    auto *grid = new QGridLayout(parent);
    grid->setHorizontalSpacing(8);
    grid->setVerticalSpacing(2);
    grid->setColumnStretch(4, 1);
    return grid;
}

void ParameterField::addToGrid(QGridLayout *grid, int row)
{
    grid->addWidget(m_marker, row, 0);
    grid->addWidget(m_label, row, 1);
    grid->addWidget(m_spin, row, 2);
    grid->addWidget(m_unit, row, 3);
    grid->addWidget(m_slider, row, 4);
    grid->addWidget(m_message, row + 1, 1, 1, 4);
}

double ParameterField::displayScale() const
{
    return m_spec.angle && m_degrees ? kDegreesPerRadian : 1.0;
}

double ParameterField::sliderToValue(int position) const
{
    const double t = static_cast<double>(position) / kSliderTicks;
    if (m_spec.logSlider) {
        const double lo = std::log10(m_spec.sliderMin);
        const double hi = std::log10(m_spec.sliderMax);
        return roundSignificant(std::pow(10.0, lo + t * (hi - lo)), 3);
    }
    const double v = m_spec.sliderMin + t * (m_spec.sliderMax - m_spec.sliderMin);
    // Values next to zero would otherwise show as 1e-17-style noise.
    const double resolution = (m_spec.sliderMax - m_spec.sliderMin) / kSliderTicks;
    return std::abs(v) < resolution / 2 ? 0.0 : roundSignificant(v, 4);
}

int ParameterField::valueToSlider(double value) const
{
    double t = 0;
    if (m_spec.logSlider) {
        const double lo = std::log10(m_spec.sliderMin);
        const double hi = std::log10(m_spec.sliderMax);
        t = value > 0 ? (std::log10(value) - lo) / (hi - lo) : 0.0;
    } else {
        t = (value - m_spec.sliderMin) / (m_spec.sliderMax - m_spec.sliderMin);
    }
    if (!std::isfinite(t))
        t = 0;
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderTicks));
}

void ParameterField::setValue(double value)
{
    if (value != m_value && !m_note.isEmpty()) {
        m_note.clear(); // the note spoke of an entry this value replaces
        updateMessage();
    }
    m_value = value;
    updateSpinRange(); // the range follows the value: shown as it is, never a bound instead
    updateSlider();
    updateMarker();
}

void ParameterField::updateSlider()
{
    // While the user drags, the handle already stands for this value: leave it alone so the
    // rounding of the slider mapping cannot make it jitter.
    if (sliderToValue(m_slider->value()) == m_value)
        return;
    const QSignalBlocker block(m_slider);
    m_slider->setValue(valueToSlider(m_value));
}

void ParameterField::updateSpinRange()
{
    // The spec's range, widened to a value set from outside the rules (a run-time maximum
    // that fell below it, say): the field shows what it holds, and its message the rule.
    const double scale = displayScale();
    const bool finite = std::isfinite(m_value);
    const double low = finite ? std::min(m_spec.minimum, m_value) : m_spec.minimum;
    const double high = finite ? std::max(m_spec.maximum, m_value) : m_spec.maximum;
    const QSignalBlocker block(m_spin);
    m_spin->setRange(low * scale, high * scale);
    m_spin->setExclusiveBounds(m_spec.minimumExclusive, m_spec.maximumExclusive);
    m_spin->setSingleStep(m_spec.step * scale);
    m_spin->setValue(m_value * scale);
}

void ParameterField::setAngleInDegrees(bool degrees)
{
    if (!m_spec.angle || degrees == m_degrees)
        return;
    m_degrees = degrees;
    m_unit->setText(degrees ? QStringLiteral("°") : m_spec.unit);
    updateSpinRange();
    updateMarker();
}

void ParameterField::setUnit(const QString &unit)
{
    m_spec.unit = unit;
    if (!(m_spec.angle && m_degrees))
        m_unit->setText(unit);
}

void ParameterField::setProblem(const QString &problem)
{
    if (problem == m_problem)
        return;
    m_problem = problem;
    m_spin->setProperty("invalid", !problem.isEmpty());
    m_spin->setStyleSheet(problem.isEmpty() ? QString() : kInvalidStyle);
    updateMessage();
    const QString tip = u"<b>"_s + m_spec.symbol + u"</b> — "_s + m_spec.meaning + u" ["_s +
                        m_spec.unit + u"]<br>"_s + m_spec.toolTip;
    m_spin->setToolTip(problem.isEmpty()
                           ? tip
                           : tip + u"<br><span style=\"color:"_s + palette::kProblemText.name() +
                                 u"\">"_s + problem + u"</span>"_s);
}

void ParameterField::setMaximum(double maximum, bool exclusive)
{
    if (maximum == m_spec.maximum && exclusive == m_spec.maximumExclusive)
        return;
    m_spec.maximum = maximum;
    m_spec.maximumExclusive = exclusive;
    updateSpinRange();
}

QString ParameterField::unitSuffix() const
{
    return m_spec.angle && m_degrees ? QStringLiteral("°") : u" "_s + m_spec.unit;
}

void ParameterField::showClamp(double typed, double bound)
{
    // Every field treats out-of-range typing alike: the nearest bound, said out loud.
    const bool above = typed > bound;
    m_note =
        tr("%1: %2 is %3 the %4 %5%6, set to %5")
            .arg(m_spec.symbol, QString::number(typed, 'g', 6), above ? tr("above") : tr("below"),
                 above ? tr("maximum") : tr("minimum"), m_spin->textFromValue(bound), unitSuffix());
    updateMessage();
}

void ParameterField::showRefusal(double typed, double bound)
{
    // The bound breaks the rule too (N > 0): no value near what was typed is valid, so the
    // field keeps its value and says which rule the typed one broke.
    const bool above = typed > bound;
    const double rule = (above ? m_spec.maximum : m_spec.minimum) * displayScale();
    m_note =
        tr("%1: %2 is refused: %1 must be %3 %4%5; it stays %6")
            .arg(m_spec.symbol, QString::number(typed, 'g', 6),
                 above ? QStringLiteral("<") : QStringLiteral(">"), m_spin->textFromValue(rule),
                 unitSuffix(), m_spin->textFromValue(m_spin->value()) + unitSuffix());
    updateMessage();
}

void ParameterField::showNotANumber(const QString &typed)
{
    m_note = tr("%1: “%2” is not a number; it stays %3")
                 .arg(m_spec.symbol, typed, m_spin->textFromValue(m_spin->value()) + unitSuffix());
    updateMessage();
}

void ParameterField::updateMessage()
{
    // A broken rule comes first (it blocks the push), and the note on the entry after it: the
    // rule names the value the field holds, the note what became of the text typed.
    QStringList lines;
    if (!m_problem.isEmpty())
        lines << m_problem;
    if (!m_note.isEmpty())
        lines << m_note;
    const QString text = lines.join(u'\n');
    m_message->setStyleSheet(m_problem.isEmpty() ? kClampStyle : kProblemStyle);
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

void ParameterField::setDeviceValue(std::optional<double> deviceValue)
{
    m_device = deviceValue;
    updateMarker();
}

bool ParameterField::differsFromDevice() const
{
    // Device fields compare as they travel (float32, kept inside inclusive bounds); the host
    // fields (v_max, tau_limit) never travel and compare the same way for consistency.
    const int index = deviceFieldIndex(m_spec.key.toStdString());
    return m_device && roundedForWire(index, *m_device) != roundedForWire(index, m_value);
}

QString ParameterField::numberText(double value) const
{
    return QString::number(value * displayScale(), 'g', 6) + unitSuffix();
}

void ParameterField::updateMarker()
{
    const bool differs = differsFromDevice();
    m_marker->setVisible(differs);
    m_marker->setToolTip(differs ? tr("device: %1").arg(numberText(*m_device)) : QString());
}

} // namespace hatpic
