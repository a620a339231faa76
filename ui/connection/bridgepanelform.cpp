#include "connection/bridgepanelform.h"

#include <QDoubleSpinBox>

namespace hatpic::bridgeform {

QDoubleSpinBox *spin(QWidget *parent, const QString &name, double low, double high, int decimals,
                     const QString &suffix)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(low, high);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    return box;
}

// The box's value, or `original` when the box still shows it (rounded to its decimals): an
// edit elsewhere in the panel keeps every digit the profile had.
double taken(const QDoubleSpinBox *box, double original)
{
    const double shown = QString::number(original, 'f', box->decimals()).toDouble();
    return box->value() == shown ? original : box->value();
}

} // namespace hatpic::bridgeform
