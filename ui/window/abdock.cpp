#include "window/abdock.h"

#include "blindtest/blinddialog.h"
#include "blindtest/blindrunner.h"
#include "editor/parametereditor.h"
#include "profiles/abcomparepanel.h"
#include "profiles/profilecontroller.h"
#include "profiles/profilenotesedit.h"
#include "stiffness/stiffnessview.h"

#include <QDate>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>
#include <QStandardPaths>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QDockWidget *dock(QMainWindow *window, const QString &title, const QString &name, QWidget *widget,
                  QDockWidget *tabWith)
{
    auto *d = new QDockWidget(title, window);
    d->setObjectName(name);
    d->setWidget(widget);
    window->addDockWidget(Qt::BottomDockWidgetArea, d);
    if (tabWith)
        window->tabifyDockWidget(tabWith, d);
    d->hide();
    return d;
}

//! A new trials file's name: in the profiles' folder, dated.
QString suggestedTrialsFile()
{
    QString dir = QSettings().value(QString::fromUtf16(ProfileController::kLastDirKey)).toString();
    if (dir.isEmpty() || !QFileInfo(dir).isDir())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString stem = u"blind-ab-"_s + QDate::currentDate().toString(Qt::ISODate);
    QString path = QDir(dir).filePath(stem + u".csv"_s);
    for (int i = 2; QFileInfo::exists(path) && i < 1000; ++i)
        path = QDir(dir).filePath(stem + u'-' + QString::number(i) + u".csv"_s);
    return path;
}

} // namespace

QList<QDockWidget *> addAbDocks(QMainWindow *window, ProfileController *profiles,
                                TuningModel *tuning, ParameterEditor *editor,
                                StiffnessView *stiffness, QDockWidget *tabWith)
{
    auto *panel = new AbComparePanel(profiles, window);
    panel->setObjectName(u"abComparePanel"_s);
    auto *notes = new ProfileNotesEdit(profiles, window);
    QDockWidget *abDock = dock(window, QObject::tr("A/B"), u"abDock"_s, panel, tabWith);
    QDockWidget *notesDock = dock(window, QObject::tr("Notes"), u"notesDock"_s, notes, tabWith);

    // Both slots' curves in the stiffness view once B exists.
    auto compare = [profiles, stiffness] {
        const int other = 1 - profiles->activeSlot();
        if (profiles->isSlotUsed(other))
            stiffness->setComparison(profiles->slotProfile(other).device, profiles->activeSlot(),
                                     profiles->slotProfile(other).effects);
        else
            stiffness->setComparison(std::nullopt, profiles->activeSlot());
    };
    QObject::connect(profiles, &ProfileController::slotsChanged, stiffness, compare);
    compare();
    panel->setAngleInDegrees(editor->angleInDegrees());
    QObject::connect(editor, &ParameterEditor::angleInDegreesChanged, panel,
                     &AbComparePanel::setAngleInDegrees);

    auto *runner = new BlindRunner(profiles, tuning, window);
    runner->setObjectName(u"blindRunner"_s);
    auto *dialog = new BlindDialog(runner, window);
    QObject::connect(panel, &AbComparePanel::blindTestRequested, dialog, [dialog] {
        dialog->prepare(suggestedTrialsFile());
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    // While blind the main window is out of sight: its title names the slot, the editor and
    // the A/B table show the values, the stiffness view the curves, the status bar the pushes.
    QObject::connect(runner, &BlindRunner::runningChanged, window, [window, dialog](bool running) {
        window->setVisible(!running);
        if (!running)
            dialog->raise();
    });
    return {abDock, notesDock};
}

} // namespace hatpic
