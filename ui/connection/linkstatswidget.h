// Status-bar figures of the link: frames/s, dropped frames, decoder errors, round-trip time.
#pragma once

#include "session/sessiontypes.h"

#include <QLabel>

namespace hatpic {

class LinkStatsWidget : public QLabel
{
    Q_OBJECT
public:
    explicit LinkStatsWidget(QWidget *parent = nullptr);

    void setStats(const LinkStats &stats);
    void clear();
};

} // namespace hatpic
