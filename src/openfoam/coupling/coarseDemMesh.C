#include "coarseDemMesh.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"

#include <type_traits>

static_assert(sizeof(Foam::label) == sizeof(int32_t), "coarse-dem needs 32-bit labels");
static_assert(sizeof(Foam::vector) == 3*sizeof(double), "coarse-dem needs vector = 3 doubles");

Foam::coarseDemMesh::coarseDemMesh(const fvMesh& mesh, const dictionary& couplingDict)
:
    mesh_(mesh),
    ctx_(nullptr)
{
    const faceList& faces = mesh.faces();
    faceOffsets_.resize(faces.size() + 1);
    faceOffsets_[0] = 0;
    forAll(faces, facei)
    {
        faceOffsets_[facei + 1] = faceOffsets_[facei] + faces[facei].size();
    }
    facePoints_.resize(faceOffsets_.back());
    forAll(faces, facei)
    {
        std::copy(faces[facei].begin(), faces[facei].end(), facePoints_.begin() + faceOffsets_[facei]);
    }

    // patches that are walls for the DEM but inlets or outlets for the fluid (a distributor plate)
    const wordRes mirrorPatches(couplingDict.lookupOrDefault<wordRes>("mirrorPatches", wordRes()));
    for (const wordRe& name : mirrorPatches)
    {
        bool found = false;
        for (const polyPatch& pp : mesh.boundaryMesh()) found = found || name.match(pp.name());
        if (!found)
        {
            FatalIOErrorInFunction(couplingDict)
                << "entry mirrorPatches in " << couplingDict.name() << ": " << name
                << " matches no patch of the mesh" << nl << "    patches: " << mesh.boundaryMesh().names()
                << exit(FatalIOError);
        }
    }

    const label nInternal = mesh.nInternalFaces();
    boundaryKind_.assign(mesh.nFaces() - nInternal, CDC_FACE_OTHER);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        uint8_t kind = CDC_FACE_OTHER;
        // a symmetry plane mirrors the flow, so kernels mirror across it like across a wall
        if
        (
            isA<wallPolyPatch>(pp) || isA<symmetryPolyPatch>(pp) || isA<symmetryPlanePolyPatch>(pp)
         || mirrorPatches.match(pp.name())
        )
        {
            kind = CDC_FACE_WALL;
        }
        else if (isA<processorPolyPatch>(pp)) kind = CDC_FACE_PROCESSOR;
        for (label i = 0; i < pp.size(); ++i)
        {
            boundaryKind_[pp.start() + i - nInternal] = kind;
        }
    }

    view_.n_points = mesh.nPoints();
    view_.n_cells = mesh.nCells();
    view_.n_faces = mesh.nFaces();
    view_.n_internal_faces = nInternal;
    view_.points = reinterpret_cast<const double*>(mesh.points().cdata());
    view_.face_point_offsets = faceOffsets_.data();
    view_.face_points = facePoints_.data();
    view_.owner = mesh.faceOwner().cdata();
    view_.neighbour = mesh.faceNeighbour().cdata();
    view_.face_centres = reinterpret_cast<const double*>(mesh.faceCentres().cdata());
    view_.face_areas = reinterpret_cast<const double*>(mesh.faceAreas().cdata());
    view_.cell_centres = reinterpret_cast<const double*>(mesh.cellCentres().cdata());
    view_.cell_volumes = mesh.cellVolumes().cdata();
    view_.boundary_face_kind = boundaryKind_.data();

    const cdc_status st = cdc_context_create(&view_, &ctx_);
    if (st != CDC_OK)
    {
        FatalErrorInFunction
            << "mesh " << mesh.polyMesh::path() << ": " << cdc_create_error() << nl
            << "    (check the mesh with checkMesh)" << exit(FatalError);
    }
    if (Pstream::parRun())
    {
        setHalo();
        setGlobalWallFacets();
    }
}

// Every rank gets the wall faces of the whole mesh (centre, area, owner cell centre), so that the
// kernels of particles near a processor boundary choose their mirror facets among the same faces
// as in a serial run (on a curved wall the nearest facet may be in the other rank's part).
void Foam::coarseDemMesh::setGlobalWallFacets()
{
    const label nInternal = mesh_.nInternalFaces();
    List<List<vector>> facets(Pstream::nProcs());   // per rank: centre, area, owner centre per face
    DynamicList<vector> mine;
    for (label f = nInternal; f < mesh_.nFaces(); ++f)
    {
        if (boundaryKind_[f - nInternal] != CDC_FACE_WALL) continue;
        mine.append(mesh_.faceCentres()[f]);
        mine.append(mesh_.faceAreas()[f]);
        mine.append(mesh_.cellCentres()[mesh_.faceOwner()[f]]);
    }
    facets[Pstream::myProcNo()].transfer(mine);
    Pstream::gatherList(facets);
    Pstream::scatterList(facets);
    label n = 0;
    for (const List<vector>& l : facets) n += l.size()/3;
    std::vector<double> centres, areas, owners;
    centres.reserve(3*n);
    areas.reserve(3*n);
    owners.reserve(3*n);
    for (const List<vector>& l : facets)
    {
        for (label i = 0; i < l.size(); i += 3)
        {
            for (direction d = 0; d < 3; ++d)
            {
                centres.push_back(l[i][d]);
                areas.push_back(l[i + 1][d]);
                owners.push_back(l[i + 2][d]);
            }
        }
    }
    check(cdc_context_set_wall_facets(ctx_, int32_t(n), centres.data(), areas.data(), owners.data()),
          "wall facets of the whole mesh");
}

void Foam::coarseDemMesh::setHalo()
{
    haloField_.reset
    (
        new volScalarField
        (
            IOobject("coarseDemHalo", mesh_.time().timeName(), mesh_, IOobject::NO_READ, IOobject::NO_WRITE, false),
            mesh_, dimensionedScalar(dimless, Zero)
        )
    );
    // The two sides compute |S_f| in different orders (the face is stored reversed), so it agrees
    // only to round-off: each side uses the mean of both, and the flux leaving one rank is then
    // bit for bit the flux entering the other (delta() is exactly opposite on the two sides).
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (const fvPatch& fp : mesh_.boundary())
    {
        if (!diffusesAcross(fp)) continue;
        UOPstream toNbr(refCast<const processorPolyPatch>(fp.patch()).neighbProcNo(), buffers);
        toNbr << fp.magSf();
    }
    buffers.finishedSends();
    for (const fvPatch& fp : mesh_.boundary())
    {
        if (!diffusesAcross(fp)) continue;
        UIPstream fromNbr(refCast<const processorPolyPatch>(fp.patch()).neighbProcNo(), buffers);
        const scalarField nbrMagSf(fromNbr);
        // delta(): from this cell's centre to the neighbour rank's cell centre
        const vectorField d(fp.delta());
        const scalarField& magSf = fp.magSf();
        forAll(fp, i)
        {
            haloCells_.push_back(fp.faceCells()[i]);
            haloCoeff_.push_back(0.5*(magSf[i] + nbrMagSf[i])/mag(d[i]));
        }
    }
    haloNbrVolume_.resize(haloCells_.size());
    exchange(mesh_.V().cdata(), haloNbrVolume_.data());

    cdc_halo h = {int32_t(haloCells_.size()), haloCells_.data(), haloCoeff_.data(), haloNbrVolume_.data(),
                  &haloExchange, &haloSum, this, &haloMax};
    check(cdc_context_set_halo(ctx_, &h), "processor faces for diffusion smoothing and the packing limiter");
}

void Foam::coarseDemMesh::exchange(const double* cellValues, double* nbr)
{
    volScalarField& f = *haloField_;
    std::copy(cellValues, cellValues + mesh_.nCells(), f.primitiveFieldRef().begin());
    f.correctBoundaryConditions();   // processor patches receive the neighbours' cell values
    size_t k = 0;
    for (const fvPatch& fp : mesh_.boundary())
    {
        if (!diffusesAcross(fp)) continue;
        const fvPatchScalarField& pf = f.boundaryField()[fp.index()];
        forAll(pf, i) nbr[k++] = pf[i];
    }
}

int Foam::coarseDemMesh::haloExchange(void* self, const double* cellValues, double* nbr)
{
    static_cast<coarseDemMesh*>(self)->exchange(cellValues, nbr);
    return 0;
}

bool Foam::coarseDemMesh::diffusesAcross(const fvPatch& fp)
{
    // processor faces of the decomposition; processorCyclic ones (cyclic faces split between ranks)
    // stay zero-flux, as cyclic faces are in serial
    return isA<processorPolyPatch>(fp.patch()) && !isA<processorCyclicPolyPatch>(fp.patch());
}

// values[0..n) combined over the ranks on the master and sent to all: every rank gets the same bits
template<class CombineOp>
static void combineOverRanks(double* values, int n, const CombineOp& op)
{
    Foam::List<Foam::scalar> v(n);
    std::copy(values, values + n, v.begin());
    Foam::Pstream::listCombineGather(v, op);
    Foam::Pstream::listCombineScatter(v);
    std::copy(v.begin(), v.end(), values);
}

int Foam::coarseDemMesh::haloSum(void*, double* values, int n)
{
    // the same bits on every rank, so every rank's CG takes the same decisions (an allreduce need
    // not give identical results on all ranks)
    combineOverRanks(values, n, plusEqOp<scalar>());
    return 0;
}

int Foam::coarseDemMesh::haloMax(void*, double* values, int n)
{
    combineOverRanks(values, n, maxEqOp<scalar>());
    return 0;
}

Foam::coarseDemMesh::~coarseDemMesh()
{
    cdc_context_destroy(ctx_);
}

void Foam::coarseDemMesh::check(cdc_status st, const string& what) const
{
    if (st != CDC_OK)
    {
        FatalErrorInFunction
            << what << ": " << cdc_last_error(ctx_) << nl
            << "    at time " << mesh_.time().timeName() << exit(FatalError);
    }
}
