// The JSON that profiles and recordings' metadata share: number and string text, objects with a
// fixed key order (QJsonObject would sort the keys), and the two parameter objects both files
// hold, profile.md's `device` and `host`. Written and read here, and nowhere else.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"

#include <QByteArray>
#include <QByteArrayList>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <array>

namespace hatpic {

//! A double as JSON number text that reads back as the identical double: shortest round-trip
//! digits, always with a '.' or an exponent ("0.0001", "1.0", "1e-300"); −0.0 is written
//! "0.0" (it reads back as +0.0); "null" for NaN and ±Inf, which JSON cannot hold.
QByteArray jsonNumber(double value);
//! A JSON string literal: quotes, backslash and control characters escaped, the rest UTF-8.
QByteArray jsonString(const QString &text);
QByteArray jsonBool(bool value); //!< "true", "false"
//! How a JSON value appears after "got " in a message: 0.9, "abc", an array, …
QString jsonValueText(const QJsonValue &value);

//! Writes a JSON object with keys in the order they are added, one per line:
//! "{\n<indent+2>\"key\": value,\n…\n<indent>}" ("{}" when empty).
class JsonObjectWriter
{
public:
    explicit JsonObjectWriter(int indent) : m_indent(indent) {}
    //! Adds `key` with `rawValue`, JSON text as it is written (jsonNumber(), jsonString(), …).
    JsonObjectWriter &add(const char *key, const QByteArray &rawValue);
    QByteArray text() const;

private:
    int m_indent;
    QByteArrayList m_items;
};

//! The `device` object of profile.md: every field of the parameter table, in table order.
QByteArray deviceParamsJson(const DeviceParams &params, int indent);
//! The same object still open, for a profile to add its `effects` object after those keys.
JsonObjectWriter deviceParamsWriter(const DeviceParams &params, int indent);
//! The `effects` object (effects.md § 2): every field of the effect block, in wire order.
QByteArray effectParamsJson(const EffectParams &effects, int indent);
//! The `passivity` object (passivity.md): both fields of the controller's block, in wire order.
QByteArray passivityParamsJson(const PassivityParams &passivity, int indent);
//! The `host` object of profile.md: mode, v_max, ref_deadzone, tau_limit.
QByteArray hostParamsJson(const HostParams &params, int indent);
//! The same object still open, for a profile to add its `bridge` object after those keys.
JsonObjectWriter hostParamsWriter(const HostParams &params, int indent);

//! Reads a `device` object into `params`. A field that is a number is set; one that is missing
//! or not a number is left as it is and reported in `errors` ("<prefix>K_max: missing, must be a
//! number"). Keys that name no field are reported in `warnings`, when given. No rule of
//! model.md is checked here. Returns which fields were set.
//! `otherKeys` are keys the caller reads itself (a profile's `effects`).
std::array<bool, DeviceParams::kFieldCount>
readDeviceParams(const QJsonObject &object, const QString &prefix, DeviceParams &params,
                 QStringList &errors, QStringList *warnings, const QStringList &otherKeys = {});
//! Reads an `effects` object into `effects`: a missing key keeps its value (the default), one
//! that is not a number is an error; unknown keys are warnings. No rule of effects.md is
//! checked here. Returns which fields were set.
std::array<bool, EffectParams::kFieldCount>
readEffectParams(const QJsonObject &object, const QString &prefix, EffectParams &effects,
                 QStringList &errors, QStringList &warnings);
//! Reads a `passivity` object as readEffectParams() reads an `effects` object.
std::array<bool, PassivityParams::kFieldCount>
readPassivityParams(const QJsonObject &object, const QString &prefix, PassivityParams &passivity,
                    QStringList &errors, QStringList &warnings);
//! Reads a `host` object into `params` as readDeviceParams() does, except that a missing key is
//! no error (it keeps its value). `otherKeys` are keys the caller reads itself (a profile's
//! `bridge`), so no warning names them. Returns the names of the number fields that held
//! something else.
QStringList readHostParams(const QJsonObject &object, const QString &prefix, HostParams &params,
                           QStringList &errors, QStringList *warnings,
                           const QStringList &otherKeys = {});

//! Most unknown keys of one object named, one warning each; the rest are counted in one more.
inline constexpr int kMaxUnknownKeysNamed = 10;
//! Reports the keys of `object` that `known` does not hold as warnings: "unknown key
//! \"<prefix>colour\" ignored", each key quoted as echoedText() does (printable, cut); beyond
//! kMaxUnknownKeysNamed, one "… and 49990 more unknown keys in \"<prefix>\" ignored".
void warnUnknownKeys(const QJsonObject &object, const QStringList &known, const QString &prefix,
                     QStringList &warnings);

} // namespace hatpic
