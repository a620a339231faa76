// effects_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-effects.png: the real main
// window on the built-in simulator with the Detents preset pushed (so the device renders the
// detents), the editor scrolled to its Effects section, and the gentle hand turning the knob
// through the clicks. Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/effects_screenshot
//   docs/screenshot-effects.png
#include "editor/parametereditor.h"
#include "profile/profile.h"
#include "screenshotwindow.h"

#include <QAction>
#include <QGroupBox>
#include <QScrollArea>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(argc, argv, "effects_screenshot", 12000, [](MainWindow &window, QSize) {
        QTimer::singleShot(2500, &window, [&window] {
            auto *editor = window.findChild<ParameterEditor *>(QStringLiteral("parameterEditor"));
            const Profile detents = *preset(QStringLiteral("Detents"));
            Tuning t = editor->tuning();
            t.device = detents.device;
            t.effects = detents.effects;
            editor->setTuning(t, QStringLiteral("Detents"));
            editor->pushAction()->trigger();
            auto *group = editor->findChild<QGroupBox *>(QStringLiteral("group_effects"));
            if (auto *scroll = editor->findChild<QScrollArea *>())
                scroll->ensureWidgetVisible(group, 0, 0);
        });
    });
}
