// The one way to include QCustomPlot in this project.
//
// qcustomplot.h (2.1) still spells `signals` and `foreach`, which QT_NO_KEYWORDS removes; the
// two words are mapped to their Q_ forms only while the header is read.
#pragma once

#define signals Q_SIGNALS
#define foreach Q_FOREACH
#include <qcustomplot.h>
#undef signals
#undef foreach
