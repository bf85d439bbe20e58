#include "particleHalo.H"
#include "PstreamBuffers.H"

Foam::particleHalo::particleHalo(const fvMesh& mesh)
:
    procBoxes_(Pstream::nProcs()),
    sendIdx_(Pstream::nProcs()),
    recvStart_(Pstream::nProcs(), 0),
    recvSize_(Pstream::nProcs(), 0),
    nGhosts_(0)
{
    procBoxes_[Pstream::myProcNo()] = boundBox(mesh.points(), false);
    Pstream::gatherList(procBoxes_);
    Pstream::scatterList(procBoxes_);
}

void Foam::particleHalo::update
(
    const demParticles& local, const std::vector<double>& reach, demParticles& ghosts
)
{
    const label n = local.size();
    forAll(sendIdx_, proci) sendIdx_[proci].clear();
    if (!active())
    {
        nGhosts_ = 0;
        ghosts = demParticles();
        return;
    }
    // which ranks each particle's kernel reaches (distance from the centre to the rank's box)
    List<DynamicList<label>> dest(Pstream::nProcs());
    for (label i = 0; i < n; ++i)
    {
        const point x(local.x[3*i], local.x[3*i + 1], local.x[3*i + 2]);
        forAll(procBoxes_, proci)
        {
            if (proci == Pstream::myProcNo()) continue;
            const boundBox& bb = procBoxes_[proci];
            const point nearest(max(bb.min().x(), min(x.x(), bb.max().x())),
                                max(bb.min().y(), min(x.y(), bb.max().y())),
                                max(bb.min().z(), min(x.z(), bb.max().z())));
            if (magSqr(nearest - x) <= sqr(reach[i])) dest[proci].append(i);
        }
    }
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(dest, proci)
    {
        sendIdx_[proci].transfer(dest[proci]);
        if (sendIdx_[proci].empty()) continue;
        const labelList& idx = sendIdx_[proci];
        scalarList buf(8*idx.size());
        forAll(idx, k)
        {
            const label i = idx[k];
            for (int d = 0; d < 3; ++d) buf[8*k + d] = local.x[3*i + d];
            for (int d = 0; d < 3; ++d) buf[8*k + 3 + d] = local.v[3*i + d];
            buf[8*k + 6] = local.radius[i];
            buf[8*k + 7] = scalar(local.id[i]);   // ids < 2^53 are exact in a double
        }
        UOPstream os(proci, pBufs);
        os << buf;
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);
    ghosts = demParticles();
    nGhosts_ = 0;
    forAll(recvSizes, proci)
    {
        recvStart_[proci] = nGhosts_;
        recvSize_[proci] = 0;
        if (proci == Pstream::myProcNo() || recvSizes[proci] == 0) continue;
        UIPstream is(proci, pBufs);
        scalarList buf(is);
        const label m = buf.size()/8;
        for (label k = 0; k < m; ++k)
        {
            for (int d = 0; d < 3; ++d) ghosts.x.push_back(buf[8*k + d]);
            for (int d = 0; d < 3; ++d) ghosts.v.push_back(buf[8*k + 3 + d]);
            ghosts.radius.push_back(buf[8*k + 6]);
            ghosts.id.push_back(static_cast<long long>(buf[8*k + 7]));
        }
        recvSize_[proci] = m;
        nGhosts_ += m;
    }
    ghosts.density.assign(nGhosts_, 0);
    ghosts.type.assign(nGhosts_, 0);
}

void Foam::particleHalo::toGhosts(const double* local, int ncomp, std::vector<double>& ghostValues) const
{
    ghostValues.assign(size_t(nGhosts_)*ncomp, 0.0);
    if (!active()) return;
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendIdx_, proci)
    {
        const labelList& idx = sendIdx_[proci];
        if (idx.empty()) continue;
        scalarList buf(ncomp*idx.size());
        forAll(idx, k) for (int c = 0; c < ncomp; ++c) buf[ncomp*k + c] = local[ncomp*idx[k] + c];
        UOPstream os(proci, pBufs);
        os << buf;
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);
    forAll(recvSize_, proci)
    {
        if (recvSize_[proci] == 0) continue;
        UIPstream is(proci, pBufs);
        scalarList buf(is);
        for (label k = 0; k < recvSize_[proci]; ++k)
            for (int c = 0; c < ncomp; ++c) ghostValues[size_t(recvStart_[proci] + k)*ncomp + c] = buf[ncomp*k + c];
    }
}

void Foam::particleHalo::addToOwners(const double* ghostValues, int ncomp, double* local) const
{
    if (!active()) return;
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(recvSize_, proci)
    {
        if (recvSize_[proci] == 0) continue;
        scalarList buf(ncomp*recvSize_[proci]);
        forAll(buf, k) buf[k] = ghostValues[size_t(recvStart_[proci])*ncomp + k];
        UOPstream os(proci, pBufs);
        os << buf;
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);
    forAll(sendIdx_, proci)
    {
        const labelList& idx = sendIdx_[proci];
        if (idx.empty()) continue;
        UIPstream is(proci, pBufs);
        scalarList buf(is);
        forAll(idx, k) for (int c = 0; c < ncomp; ++c) local[ncomp*idx[k] + c] += buf[ncomp*k + c];
    }
}
