// Saving a plot as a picture with a caption (the profile's name and the parameters) drawn above
// it: PNG at a chosen size in pixels, SVG (vector) at a chosen size. The plot itself is not
// changed.
#pragma once

#include "model/params.h"

#include <QSize>
#include <QString>

#include <optional>

class QCustomPlot;

namespace hatpic {

struct PlotImageOptions
{
    QSize size{1920, 1080}; //!< of the whole image, caption included [px]
    //! PNG: device pixels per layout pixel (2: the plot drawn at half the size, twice as sharp,
    //! so the text keeps its proportion on a large image). SVG ignores it.
    double scale = 1.0;
    QString caption; //!< drawn above the plot, wrapped; empty: none
};

enum class PlotImageFormat { Png, Svg, Pdf };

//! The format a path's suffix asks for: ".svg" SVG, ".pdf" PDF, anything else PNG.
PlotImageFormat plotImageFormat(const QString &path);

//! "Profile Notchy — D_adm = 0.0001 kg·m², M_adm = 0.01 N·m·s/rad, …, tau_limit = 0.44 N·m":
//! what an exported picture is noted with. `params` nullopt: "parameters unknown".
QString plotCaption(const QString &profileName, const std::optional<DeviceParams> &params,
                    const HostParams &host);

//! Writes `plot` to `path` in the format of its suffix; false with `error` when it cannot.
//! PDF keeps the plot's on-screen size and has no caption.
bool writePlotImage(QCustomPlot *plot, const QString &path, const PlotImageOptions &options,
                    QString *error = nullptr);

} // namespace hatpic
