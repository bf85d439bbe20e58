/*---------------------------------------------------------------------------*\
    kernelTransfer: see kernelTransfer.H.
\*---------------------------------------------------------------------------*/
#include "kernelTransfer.H"

#include <algorithm>

namespace Foam
{

void kernelTransfer::gather(const cdc_kernels* k, const double* field, int ncomp, double* out)
{
    const label n = particles_.size(), ng = ghosts_.size();
    buffer_.resize(size_t(n + ng)*ncomp);
    demMesh_.check(cdc_gather(k, field, ncomp, buffer_.data()), "gather");
    halo_.addToOwners(buffer_.data() + size_t(n)*ncomp, ncomp, buffer_.data());
    std::copy(buffer_.begin(), buffer_.begin() + size_t(n)*ncomp, out);
}

void kernelTransfer::gatherTogether(const cdc_kernels* k, label nCells, const std::vector<field>& fields)
{
    const label n = particles_.size();
    int width = 0;
    for (const field& f : fields) width += f.ncomp;
    packedCells_.resize(size_t(nCells)*width);
    int at = 0;
    for (const field& f : fields)
    {
        for (label c = 0; c < nCells; ++c)
            for (int d = 0; d < f.ncomp; ++d) packedCells_[size_t(c)*width + at + d] = f.cells[size_t(c)*f.ncomp + d];
        at += f.ncomp;
    }
    packedParticles_.resize(size_t(n)*width);
    gather(k, packedCells_.data(), width, packedParticles_.data());
    at = 0;
    for (const field& f : fields)
    {
        for (label i = 0; i < n; ++i)
            for (int d = 0; d < f.ncomp; ++d) f.particles[size_t(i)*f.ncomp + d] = packedParticles_[size_t(i)*width + at + d];
        at += f.ncomp;
    }
}

void kernelTransfer::spread(const cdc_kernels* k, const double* local, int ncomp, double* out)
{
    withGhosts(local, ncomp, buffer_);
    demMesh_.check(cdc_spread(k, buffer_.data(), ncomp, out), "spread");
}

void kernelTransfer::withGhosts(const double* local, int ncomp, std::vector<double>& all)
{
    const label n = particles_.size();
    halo_.toGhosts(local, ncomp, ghostBuffer_);
    all.assign(local, local + size_t(n)*ncomp);
    all.insert(all.end(), ghostBuffer_.begin(), ghostBuffer_.end());
}

} // End namespace Foam
