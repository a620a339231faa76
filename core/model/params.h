// Parameters of the HATPIC haptic model (model.md § 1), as plain value types.
//
// Plain C++20, no Qt: firmware can compile this folder unchanged.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace hatpic {

//! Parameters the device renders. Field order is the protocol's ParamBlock order.
struct DeviceParams
{
    double D_adm = 1.0e-4; //!< virtual inertia of the admittance filter [kg·m²]
    double M_adm = 1.0e-2; //!< virtual damping of the admittance filter [N·m·s/rad]
    double K_min = 0.15;   //!< minimum re-centering stiffness [N·m/rad]
    double K_max = 0.40;   //!< maximum (notch) re-centering stiffness [N·m/rad]
    double N = 0.10;       //!< half-width of the notch band [rad]
    double Q_dz = 0.02;    //!< half-width of the dead zone [rad]
    double theta0 = 0.0;   //!< center (idle) angle [rad]

    static constexpr int kFieldCount = 7;

    //! Field by ParamBlock index 0…6; out-of-range indices give NaN.
    double field(int index) const;
    //! Sets a field by ParamBlock index; out-of-range indices are ignored.
    void setField(int index, double value);

    friend bool operator==(const DeviceParams &, const DeviceParams &) = default;
};

//! Names of the device fields in ParamBlock order ("D_adm", …, "theta0").
std::string_view deviceFieldName(int index);
//! ParamBlock index of a device field name, or -1.
int deviceFieldIndex(std::string_view name);

enum class ReferenceMode {
    Translation, //!< v_ref in m/s, p_ref in m
    Rotation,    //!< v_ref in rad/s, p_ref in rad
};

std::string_view referenceModeName(ReferenceMode mode);

//! Settings of the host-side reference model; never sent to the device.
struct HostParams
{
    double v_max = 1.0;                              //!< maximum reference velocity [m/s or rad/s]
    ReferenceMode mode = ReferenceMode::Translation; //!< unit family of v_ref and p_ref
    bool ref_deadzone = true;                        //!< hold v_ref at 0 while |θ−θ0| < Q_dz
    double tau_limit = 0.44;                         //!< actuator torque limit [N·m]

    friend bool operator==(const HostParams &, const HostParams &) = default;
};

//! One broken rule: which field, which rule, which value.
struct Violation
{
    std::string field; //!< e.g. "K_min"
    int index = -1;    //!< ParamBlock index for device fields, -1 for host fields
    std::string rule;  //!< e.g. "must be ≤ K_max (0.4)"
    double value = 0;  //!< the offending value

    //! "K_min: must be ≤ K_max (0.4), got 0.9"
    std::string message() const;
};

//! Every violated rule of model.md § 1, in table order. Empty means valid.
std::vector<Violation> validate(const DeviceParams &params);
std::vector<Violation> validate(const HostParams &params);

//! Index of the first violating device field (the device's reject reply), or -1 when valid.
int firstViolatingField(const DeviceParams &params);

//! The set as a device keeps it: every field rounded to the nearest float32, nothing adjusted
//! (unlike roundedForWire(), a value that rounds out of its range stays out and is refused).
DeviceParams roundedToFloat(const DeviceParams &params);

//! The set as it travels in a v2 ParamBlock: every field rounded to the nearest float32, except
//! that a value which satisfied a single-field bound and left it by rounding (1e-6, π/2, ±π are
//! not floats) is moved one float toward the inside. Values already outside are kept as they are,
//! so the device still refuses them. Cross-field rules are not adjusted.
DeviceParams roundedForWire(const DeviceParams &params);
//! One field of roundedForWire(): `value` at ParamBlock `index`, as the wire carries it.
double roundedForWire(int index, double value);
//! True when both sets travel as the same ParamBlock (what "in sync" means).
bool sameOnWire(const DeviceParams &a, const DeviceParams &b);

//! A value a device sent as float32, as the decimal that names that float: 0.44f arrives as
//! 0.43999999761581421 and becomes 0.44 again, so it compares equal to a profile's 0.44 and
//! does not litter files with noise digits. Values that are not exactly a float are returned
//! unchanged.
double shortestFloatDecimal(double value);
//! Each field through shortestFloatDecimal(): a block read from a device, as a person would
//! write it (sending it back gives the device the identical floats). Every writer of a
//! device's values (hatpicctl, the --state file's SAVE_PARAMS) uses it.
DeviceParams tidyDeviceParams(const DeviceParams &params);

//! Shortest decimal text that reads back as the same double ("0.4", "1e-06", "nan").
std::string formatNumber(double value);

//! Longest text a message quotes whole [bytes].
inline constexpr std::size_t kMaxEchoedBytes = 64;
//! Text a person gave (a topic name, an option's value) as a message quotes it: whole up to
//! kMaxEchoedBytes; longer, its start cut at a UTF-8 character boundary, then "…" and its size
//! ("/aaaa…aaa… (122880 bytes)"), so a refused 120 KB value does not flood the terminal.
std::string echoedText(std::string_view text);

} // namespace hatpic
