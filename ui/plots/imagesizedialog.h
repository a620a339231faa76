// Asks the size of an exported picture: a preset (the plots' size on screen, 1280×720, HD,
// QHD, 4K) or any width and height, and for PNG the scale (how many image pixels per screen
// pixel: text and lines grow with it).
#pragma once

#include "plots/plotexport.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace hatpic {

class ImageSizeDialog : public QDialog
{
    Q_OBJECT
public:
    //! `onScreen`: the plots' size now, the first preset.
    ImageSizeDialog(const QSize &onScreen, PlotImageFormat format, QWidget *parent = nullptr);

    //! The chosen size and scale (the caption is the caller's).
    PlotImageOptions options() const;

private:
    QComboBox *m_preset = nullptr;
    QSpinBox *m_width = nullptr;
    QSpinBox *m_height = nullptr;
    QDoubleSpinBox *m_scale = nullptr;
};

} // namespace hatpic
