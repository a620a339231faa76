#include "editor/scientificspinbox.h"

#include <QKeyEvent>
#include <QLineEdit>

#include <algorithm>
#include <cmath>

namespace hatpic {

ScientificSpinBox::ScientificSpinBox(QWidget *parent) : QDoubleSpinBox(parent)
{
    // QDoubleSpinBox rounds its value to decimals(); keep enough that 1e-6 … 1e-4 survive.
    setDecimals(20);
    setLocale(QLocale::c());
    setKeyboardTracking(false);
    setAccelerated(true);
    setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
}

bool ScientificSpinBox::event(QEvent *event)
{
    // A number needs no space, and Ctrl+Z (Ctrl+Shift+Z) means the field's own undo (redo)
    // only while it has typing to undo (redo): otherwise the window's shortcuts get them
    // (pause, undo or redo the edit).
    if (event->type() == QEvent::ShortcutOverride) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier) {
            event->ignore();
            return true;
        }
        // Typing not yet committed (Enter, leaving the field) is the field's to undo.
        const bool typing =
            lineEdit()->isUndoAvailable() && lineEdit()->text() != textFromValue(value());
        if ((key->matches(QKeySequence::Undo) && !typing) ||
            (key->matches(QKeySequence::Redo) && !lineEdit()->isRedoAvailable())) {
            event->ignore();
            return true;
        }
    }
    return QDoubleSpinBox::event(event);
}

void ScientificSpinBox::setSignificantDigits(int digits)
{
    m_digits = std::clamp(digits, 1, 17);
    lineEdit()->setText(textFromValue(value()));
}

double ScientificSpinBox::tidy(double value)
{
    return QString::number(value, 'g', 12).toDouble();
}

void ScientificSpinBox::stepBy(int steps)
{
    if (m_stepMode == StepMode::Fixed) {
        QDoubleSpinBox::stepBy(steps);
        return;
    }
    double v = value();
    for (int i = 0; i < std::abs(steps); ++i) {
        const bool up = steps > 0;
        // Going down from an exact power of ten uses the finer step of the decade below.
        const double magnitude = std::abs(v) * (up ? 1.0 : 1.0 - 1e-9);
        double step = singleStep();
        if (magnitude > 0 && std::isfinite(magnitude))
            step = std::pow(10.0, std::floor(std::log10(magnitude)) - 1.0);
        v = tidy(v + (up ? step : -step));
    }
    setValue(std::clamp(v, minimum(), maximum()));
    selectAll();
}

QString ScientificSpinBox::textFromValue(double value) const
{
    return QString::number(value, 'g', m_digits);
}

double ScientificSpinBox::valueFromText(const QString &text) const
{
    // Unchanged text keeps the exact value: the display shows fewer digits than it holds.
    if (text == textFromValue(value()))
        return value();
    // A bound shows rounded (π/2 as 1.5708, just above it): its text stands for the bound.
    if (text == textFromValue(maximum()))
        return maximum();
    if (text == textFromValue(minimum()))
        return minimum();
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    return ok ? v : value();
}

void ScientificSpinBox::setExclusiveBounds(bool lower, bool upper)
{
    m_lowerExclusive = lower;
    m_upperExclusive = upper;
}

QValidator::State ScientificSpinBox::validate(QString &input, int &pos) const
{
    Q_UNUSED(pos);
    const QString t = input.trimmed();
    if (t.isEmpty())
        return QValidator::Intermediate;
    // Anything typed stays in the field as typed ("1e", "-", "0." on the way to a number, and
    // "4a.b5c" too): a key is never dropped unseen. What is not a number when the field is
    // left is refused out loud (fixup()).
    bool ok = false;
    const double v = t.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return QValidator::Intermediate;
    if (t == textFromValue(minimum()) || t == textFromValue(maximum()))
        return QValidator::Acceptable;
    if (v < minimum() || v > maximum())
        return QValidator::Intermediate;
    return QValidator::Acceptable;
}

void ScientificSpinBox::fixup(QString &input) const
{
    // fixup() is const by Qt's signature; telling the field what became of its text changes
    // nothing here.
    auto *self = const_cast<ScientificSpinBox *>(this);
    const QString typed = input.trimmed();
    bool ok = false;
    const double v = typed.toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        input = textFromValue(value());
        if (!typed.isEmpty())
            Q_EMIT self->notANumber(typed);
        return;
    }
    const double bound = std::clamp(v, minimum(), maximum());
    if (bound == v) {
        input = textFromValue(v);
        return;
    }
    if ((v < minimum() && m_lowerExclusive) || (v > maximum() && m_upperExclusive)) {
        input = textFromValue(value());
        Q_EMIT self->refused(v, bound);
        return;
    }
    input = textFromValue(bound);
    Q_EMIT self->clamped(v, bound);
}

} // namespace hatpic
