#include "plots/imagesizedialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace hatpic {

ImageSizeDialog::ImageSizeDialog(const QSize &onScreen, PlotImageFormat format, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Image size"));
    m_preset = new QComboBox(this);
    m_preset->addItem(tr("As on screen (%1×%2)").arg(onScreen.width()).arg(onScreen.height()),
                      onScreen);
    for (const QSize &size :
         {QSize(1280, 720), QSize(1920, 1080), QSize(2560, 1440), QSize(3840, 2160)})
        m_preset->addItem(tr("%1×%2").arg(size.width()).arg(size.height()), size);
    m_width = new QSpinBox(this);
    m_height = new QSpinBox(this);
    for (QSpinBox *box : {m_width, m_height}) {
        box->setRange(100, 16384);
        box->setSuffix(tr(" px"));
    }
    m_width->setValue(1920);
    m_height->setValue(1080);
    m_preset->setCurrentIndex(2); // 1920×1080
    connect(m_preset, &QComboBox::currentIndexChanged, this, [this](int) {
        const QSize size = m_preset->currentData().toSize();
        m_width->setValue(size.width());
        m_height->setValue(size.height());
    });
    m_scale = new QDoubleSpinBox(this);
    m_scale->setRange(1, 4);
    m_scale->setSingleStep(0.5);
    m_scale->setValue(1.5);
    m_scale->setSuffix(tr(" ×"));
    m_scale->setToolTip(tr("Image pixels per screen pixel: 2 draws the plots as on a screen of "
                           "half the size, with text and lines twice as large"));
    m_scale->setEnabled(format == PlotImageFormat::Png);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Preset:"), m_preset);
    form->addRow(tr("Width:"), m_width);
    form->addRow(tr("Height:"), m_height);
    form->addRow(tr("Scale (PNG):"), m_scale);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

PlotImageOptions ImageSizeDialog::options() const
{
    PlotImageOptions options;
    options.size = QSize(m_width->value(), m_height->value());
    options.scale = m_scale->value();
    return options;
}

} // namespace hatpic
