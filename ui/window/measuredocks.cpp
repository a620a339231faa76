#include "window/measuredocks.h"

#include "plots/plotactions.h"
#include "plots/plotexport.h"
#include "plots/plotpanel.h"
#include "plots/torquebreakdownview.h"
#include "plots/xyview.h"
#include "profiles/profilecontroller.h"
#include "stiffness/stiffnessview.h"
#include "tuning/tuningmodel.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>

namespace hatpic {

MeasureDocks addMeasureDocks(QMainWindow *window, PlotPanel *plots, PlotActions *plotActions,
                             ProfileController *profiles, TuningModel *tuning,
                             StiffnessView *stiffness, QMenu *view, QDockWidget *tabWith)
{
    auto dock = [&](const QString &title, const QString &name, QWidget *widget) {
        auto *d = new QDockWidget(title, window);
        d->setObjectName(name);
        d->setWidget(widget);
        window->addDockWidget(Qt::BottomDockWidgetArea, d);
        if (tabWith)
            window->tabifyDockWidget(tabWith, d);
        d->hide();
        view->addAction(d->toggleViewAction());
        return d;
    };
    auto *xy = new XyView(plots, window);
    xy->setObjectName(QStringLiteral("xyView"));
    auto *breakdown = new TorqueBreakdownView(plots, window);
    breakdown->setObjectName(QStringLiteral("torqueBreakdown"));
    MeasureDocks docks;
    docks.xy = dock(QObject::tr("XY view"), QStringLiteral("xyDock"), xy);
    docks.breakdown =
        dock(QObject::tr("Torque breakdown"), QStringLiteral("breakdownDock"), breakdown);
    // Shown again: draw at once rather than at the next repaint.
    QObject::connect(docks.xy, &QDockWidget::visibilityChanged, xy, [xy](bool on) {
        if (on)
            xy->refresh();
    });
    QObject::connect(docks.breakdown, &QDockWidget::visibilityChanged, breakdown,
                     [breakdown](bool on) {
                         if (on)
                             breakdown->refresh();
                     });

    stiffness->followTrail(plots);
    // Pictures are noted with the profile and the parameters of what the plots show (the
    // device's, or the recording's in replay; the edited ones when there are none).
    plotActions->setCaptionSource([plots, profiles, tuning] {
        const std::optional<DeviceParams> shown = plots->deviceParams();
        return plotCaption(profiles->profileName(), shown ? shown : tuning->edited().device,
                           tuning->edited().host);
    });
    return docks;
}

} // namespace hatpic
