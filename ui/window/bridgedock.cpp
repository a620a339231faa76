#include "window/bridgedock.h"

#include "connection/bridgepanel.h"
#include "profiles/profilecontroller.h"
#include "tuning/tuningmodel.h"

#include <QDockWidget>
#include <QMainWindow>

namespace hatpic {

QDockWidget *addBridgeDock(QMainWindow *window, DeviceClient *client, ProfileController *profiles,
                           TuningModel *tuning, QDockWidget *tabWith)
{
    auto *panel = new BridgePanel(*client, window);
    panel->setObjectName(QStringLiteral("bridgePanel"));
    auto *dock = new QDockWidget(QObject::tr("Bridge"), window);
    dock->setObjectName(QStringLiteral("bridgeDock"));
    dock->setWidget(panel); // it scrolls its fields itself: the window fits a 1280×720 screen
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    if (tabWith)
        window->tabifyDockWidget(tabWith, dock);

    // The profile's host.bridge: a profile opened (or the other slot) sets the panel; the
    // user's edits go to the profile, so Save profile writes them.
    panel->setSettings(profiles->bridgeSettings());
    QObject::connect(panel, &BridgePanel::settingsEdited, profiles,
                     &ProfileController::setBridgeSettings);
    QObject::connect(profiles, &ProfileController::bridgeSettingsLoaded, panel,
                     &BridgePanel::setSettings);
    panel->setReferenceMode(tuning->edited().host.mode);
    QObject::connect(tuning, &TuningModel::editedChanged, panel,
                     [panel, tuning] { panel->setReferenceMode(tuning->edited().host.mode); });
    return dock;
}

} // namespace hatpic
