// Logging category of the plots and the main window ("hatpic.ui.plots", warnings by default).
// QT_LOGGING_RULES="hatpic.ui.plots.debug=true" prints the measured repaint rate every 5 s.
#pragma once

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcPlots)
