// dark_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-dark.png: the real main window
// in View → Theme → Dark, on the built-in simulator with its gentle hand, grabbed at 1280×720
// (or WIDTH×HEIGHT) once the plots have filled. Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/dark_screenshot
//   docs/screenshot-dark.png 1280 720
#include "screenshotwindow.h"
#include "window/theme.h"

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(argc, argv, "dark_screenshot", 9000, [](MainWindow &window, QSize) {
        window.findChild<ThemeController *>(QStringLiteral("themeController"))
            ->setChoice(ThemeController::Choice::Dark);
    });
}
