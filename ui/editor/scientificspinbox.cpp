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
    // A number needs no space, and Ctrl+Z means the field's own undo only while there is
    // uncommitted typing: otherwise the window's shortcuts get them (pause, undo the edit).
    if (event->type() == QEvent::ShortcutOverride) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier) {
            event->ignore();
            return true;
        }
        // Typing not yet committed (Enter, leaving the field) is the field's to undo.
        const bool typing =
            lineEdit()->isUndoAvailable() && lineEdit()->text() != textFromValue(value());
        if (key->matches(QKeySequence::Undo) && !typing) {
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

QValidator::State ScientificSpinBox::validate(QString &input, int &pos) const
{
    Q_UNUSED(pos);
    const QString t = input.trimmed();
    if (t.isEmpty())
        return QValidator::Intermediate;
    for (const QChar c : t) {
        if (!(c.isDigit() || c == u'.' || c == u'e' || c == u'E' || c == u'-' || c == u'+'))
            return QValidator::Invalid;
    }
    bool ok = false;
    const double v = t.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return QValidator::Intermediate; // "1e", "-", "0." while typing
    if (t == textFromValue(minimum()) || t == textFromValue(maximum()))
        return QValidator::Acceptable;
    if (v < minimum() || v > maximum())
        return QValidator::Intermediate;
    return QValidator::Acceptable;
}

void ScientificSpinBox::fixup(QString &input) const
{
    bool ok = false;
    const double v = input.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        input = textFromValue(value());
        return;
    }
    const double bound = std::clamp(v, minimum(), maximum());
    input = textFromValue(bound);
    if (bound != v) {
        // fixup() is const by Qt's signature; telling the field it clamped changes nothing here.
        Q_EMIT const_cast<ScientificSpinBox *>(this)->clamped(v, bound);
    }
}

} // namespace hatpic
