// ab_screenshot OVERLAY.png BLIND.png [WIDTHxHEIGHT] — the A/B pictures of the user guide: the
// real main window on the built-in simulator with slot B (K_max 0.6, N 0.15) beside slot A,
// the A/B panel open (the overlay in the stiffness view, the differences table), then the blind
// test's window during trial 1. Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/ab_screenshot
//       docs/screenshot-ab.png docs/screenshot-blind.png
#include "blindtest/blinddialog.h"
#include "blindtest/blindrunner.h"
#include "editor/parametereditor.h"
#include "profiles/profilecontroller.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>

using namespace hatpic;

namespace {

template<typename T> T *part(const QObject *window, const char *name)
{
    return window->findChild<T *>(QString::fromLatin1(name));
}

bool save(QWidget *widget, const QString &path)
{
    const bool ok = widget->grab().save(path);
    std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(path));
    return ok;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    QSize size(1400, 900);
    if (args.size() == 3) { // WIDTHxHEIGHT
        const QStringList wh = args.takeLast().split(u'x');
        size = wh.size() == 2 ? QSize(wh[0].toInt(), wh[1].toInt()) : QSize();
    }
    if (args.size() != 2 || size.isEmpty()) {
        std::fprintf(stderr, "usage: ab_screenshot OVERLAY.png BLIND.png [WIDTHxHEIGHT]\n");
        return 2;
    }
    // The user's settings stay as they are.
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName(QStringLiteral("hatpic-screenshot"));
    QApplication::setApplicationName(QStringLiteral("hatpic-tuner"));
    const QString overlay = args[0];
    const QString blind = args[1];
    QTemporaryDir dir;

    ConnectOptions sim;
    sim.port = QStringLiteral("sim");
    MainWindow window;
    window.resize(size);
    window.show();
    window.connectTo(sim);
    auto *profiles = part<ProfileController>(&window, "profileController");
    auto *editor = part<ParameterEditor>(&window, "parameterEditor");

    QTimer::singleShot(2000, &window, [&] {
        profiles->abToggleAction()->trigger();
        DeviceParams b = editor->params();
        b.K_max = 0.6;
        b.N = 0.15;
        editor->setParams(b, editor->hostParams(), QStringLiteral("B"));
        profiles->abToggleAction()->trigger();
        editor->pushAction()->trigger();
        part<QDockWidget>(&window, "abDock")->toggleViewAction()->trigger(); // View → A/B
    });
    QTimer::singleShot(5000, &window, [&] {
        if (!save(&window, overlay))
            QApplication::exit(1);
        part<QPushButton>(&window, "ab_blind_test")->click();
        auto *dialog = part<BlindDialog>(&window, "blindDialog");
        part<QSpinBox>(dialog, "blind_trials")->setValue(10);
        part<QLineEdit>(dialog, "blind_file")->setText(dir.filePath(QStringLiteral("t.csv")));
        dialog->startStudy();
    });
    QTimer::singleShot(7000, &window, [&] {
        auto *dialog = part<BlindDialog>(&window, "blindDialog");
        QApplication::exit(save(dialog, blind) ? 0 : 1);
    });
    return app.exec();
}
