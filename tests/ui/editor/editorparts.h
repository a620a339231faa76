// The parts of a ParameterEditor its tests look at: a field's spin box, a label by its object
// name (tst_parametereditor, tst_parametereditorsync).
#pragma once

#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"

#include <QLabel>
#include <QString>

namespace hatpic::test {

inline ScientificSpinBox *spin(const ParameterEditor &editor, const QString &key)
{
    return editor.field(key)->spinBox();
}

inline QLabel *label(const ParameterEditor &editor, const QString &name)
{
    return editor.findChild<QLabel *>(name);
}

} // namespace hatpic::test
