#include "samplecsv.h"

#include "console.h"

#include <cmath>

namespace hatpic::cli {

QByteArray sampleCsvHeader()
{
    return QByteArrayLiteral("t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags\n");
}

QByteArray sampleCsvRow(const Sample &s)
{
    QByteArray row;
    row.reserve(220);
    for (const double value :
         {s.t_s, s.theta, s.omega, s.tau, s.tau_rec, s.tau_ext, s.tau_total, s.v_ref, s.p_ref}) {
        if (!std::isnan(value)) // a quantity the protocol does not carry: empty, as in recordings
            row += numberText(value).toLatin1();
        row += ',';
    }
    row += QByteArray::number(s.flags);
    row += '\n';
    return row;
}

} // namespace hatpic::cli
