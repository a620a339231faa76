// Duplicate keys in JSON text: QJsonDocument keeps only the last of them, silently, so a
// profile that names K_max twice would load one of two values without a word. This small
// scan of the text finds them.
#pragma once

#include <QByteArray>
#include <QString>

namespace hatpic {

//! The dotted path of the first key that an object of `json` names twice ("device.K_max";
//! an array's elements add "[]"), or an empty string when there is none. `json` must be
//! valid JSON (check with QJsonDocument first); the scan only follows its structure.
QString firstDuplicateKey(const QByteArray &json);

} // namespace hatpic
