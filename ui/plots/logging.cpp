#include "plots/logging.h"

Q_LOGGING_CATEGORY(lcPlots, "hatpic.ui.plots", QtWarningMsg)
