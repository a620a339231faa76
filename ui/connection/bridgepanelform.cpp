#include "connection/bridgepanelform.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QStringList>

#include <algorithm>
#include <cmath>

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

QString number(double value)
{
    return std::isfinite(value) ? QString::number(value, 'g', 4) : QStringLiteral("–");
}

QString wrenchText(const std::array<double, 6> &w)
{
    return QCoreApplication::translate("hatpic::BridgePanel",
                                       "force %1 %2 %3 N, torque %4 %5 %6 N·m")
        .arg(number(w[0]), number(w[1]), number(w[2]), number(w[3]), number(w[4]), number(w[5]));
}

QString otherComponentWarning(const std::array<double, 6> &w, bridge::Component felt)
{
    int largest = 0;
    for (int i = 1; i < 6; ++i)
        largest = std::abs(w[i]) > std::abs(w[largest]) ? i : largest;
    const bridge::Component o = *bridge::Component::fromSlot(largest);
    return QCoreApplication::translate(
               "hatpic::BridgePanel",
               "%1 stays 0 while the robot sends %2 = %3 %4: is the component right?")
        .arg(QString::fromStdString(felt.wrenchName()), QString::fromStdString(o.wrenchName()),
             number(w[largest]), o.angular ? QStringLiteral("N·m") : QStringLiteral("N"));
}

QString torquesText(const AxisTorques &torques, int knobs)
{
    const QString first = number(torques[0]) + QStringLiteral(" N·m");
    if (knobs <= 1)
        return first;
    QStringList others;
    for (int k = 1; k < knobs && k < kMaxAxes; ++k)
        others.append(number(torques[std::size_t(k)]));
    if (others.size() == 1)
        return QCoreApplication::translate("hatpic::BridgePanel", "%1; knob 2: %2 N·m")
            .arg(first, others.front());
    return QCoreApplication::translate("hatpic::BridgePanel", "%1; knobs 2–%2: %3 N·m")
        .arg(first)
        .arg(std::min(knobs, kMaxAxes))
        .arg(others.join(QStringLiteral(", ")));
}

} // namespace hatpic::bridgeform
