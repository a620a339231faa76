// How a channel is shown: the unit text, the factor from SI, and a readable value. Data stay
// SI everywhere; only what a person reads is converted (angles to degrees on request, and the
// reference channels follow the reference mode: m and m/s, or rad and rad/s).
#pragma once

#include "model/params.h"
#include "plots/channel.h"

#include <QString>

namespace hatpic {

class DisplayUnits
{
public:
    DisplayUnits() = default;
    DisplayUnits(bool degrees, ReferenceMode mode) : m_degrees(degrees), m_mode(mode) {}

    bool degrees() const { return m_degrees; }
    ReferenceMode mode() const { return m_mode; }
    void setDegrees(bool degrees) { m_degrees = degrees; }
    void setMode(ReferenceMode mode) { m_mode = mode; }

    //! Display value = SI value × scale().
    double scale(Channel channel) const;
    //! "rad", "°", "N·m", "m/s", …
    QString unit(Channel channel) const;
    //! "−3.21 °"-style text of an SI value in display units; "—" for NaN.
    QString format(Channel channel, double siValue) const;

private:
    bool isAngular(Channel channel) const; //!< measured in rad (or rad/s) in this mode

    bool m_degrees = false;
    ReferenceMode m_mode = ReferenceMode::Translation;
};

} // namespace hatpic
