#include "particleInventory.H"
#include "propsKeys.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"

namespace Foam
{

namespace
{
    //- Gather a per-rank list on every rank (a serial run: the list itself)
    template<class T>
    void allGather(List<T>& perRank)
    {
        if (!Pstream::parRun()) return;
        Pstream::gatherList(perRank);
        Pstream::scatterList(perRank);
    }
}

List<particleInventory::region> particleInventory::readRegions(const word& kind) const
{
    List<region> regions;
    const dictionary* open = dict_.findDict("openSystem");
    if (!open) return regions;
    checkPropsKeys(*open, {"inlets", "outlets"});
    const dictionary* d = open->findDict(kind);
    if (!d) return regions;
    const boundBox meshBox(mesh_.points(), true);
    for (const entry& e : *d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*d)
                << "entry " << e.keyword() << " of openSystem/" << kind << " in " << dict_.name()
                << " is not a dictionary: expected  " << e.keyword() << " { box (x0 y0 z0) (x1 y1 z1); }"
                << exit(FatalIOError);
        }
        const dictionary& rd = e.dict();
        checkPropsKeys(rd, {"box"});
        region r;
        r.name = e.keyword();
        r.box = rd.get<boundBox>("box");
        if (!r.box.valid() || r.box.volume() <= 0)
        {
            FatalIOErrorInFunction(rd)
                << "openSystem/" << kind << "/" << r.name << "/box " << r.box << " in " << dict_.name()
                << " is empty: give its lower and upper corner, (x0 y0 z0) (x1 y1 z1) with x0 < x1 etc."
                << exit(FatalIOError);
        }
        if (!r.box.overlaps(meshBox))
        {
            FatalIOErrorInFunction(rd)
                << "openSystem/" << kind << "/" << r.name << "/box " << r.box << " in " << dict_.name()
                << " lies outside the mesh " << meshBox << " (units: metres, as the mesh and the DEM)"
                << exit(FatalIOError);
        }
        regions.append(r);
    }
    return regions;
}

particleInventory::particleInventory(const fvMesh& mesh, const dictionary& couplingDict, bool allowLoss)
:
    mesh_(mesh),
    dict_(couplingDict),
    allowLoss_(allowLoss),
    inlets_(readRegions("inlets")),
    outlets_(readRegions("outlets"))
{
    elsewhere_.name = "elsewhere";
    lost_.name = "lost";
    readRestart();
}

void particleInventory::openFile()
{
    const fileName dir =
        mesh_.time().globalPath()/"postProcessing"/"particleInventory"/Time::timeName(mesh_.time().startTime().value());
    mkDir(dir);
    file_.reset(new OFstream(dir/"particleInventory.dat"));
    OFstream& f = *file_;
    f << "# particles entered and left since the run's first start (numbers, and mass in kg)" << nl
      << "# time particles mass";
    for (const region& r : inlets_) f << " in_" << r.name << " in_" << r.name << "_kg";
    f << " in_elsewhere in_elsewhere_kg";
    for (const region& r : outlets_) f << " out_" << r.name << " out_" << r.name << "_kg";
    f << " lost lost_kg mass_balance_rel_err" << endl;
}

label particleInventory::find(const List<region>& regions, const point& x)
{
    forAll(regions, i)
    {
        if (regions[i].box.contains(x)) return i;
    }
    return -1;
}

void particleInventory::record(const demParticles& p)
{
    const label n = p.size();
    ids_.setSize(n);
    x_.setSize(n);
    mass_.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar r = p.radius[i];
        ids_[i] = label(p.id[i]);
        x_[i] = point(p.x[3*i], p.x[3*i + 1], p.x[3*i + 2]);
        mass_[i] = p.density[i]*4.0/3.0*constant::mathematical::pi*r*r*r;
    }
}

void particleInventory::compare(changes& gone, changes& added)
{
    // seenAt_[id]: the coupling this rank last held particle id at. O(n) per coupling, no hashing:
    // 4 bytes per DEM id (40 MB for ids up to 10^7)
    label maxId = 0;
    for (const label id : ids_) maxId = max(maxId, id);
    if (maxId >= label(seenAt_.size())) seenAt_.resize(maxId + 1, -1);
    DynamicList<label> ids;
    DynamicList<point> xs;
    DynamicList<scalar> ms;
    forAll(ids_, i)
    {
        if (seenAt_[ids_[i]] != nCouplings_ - 1)
        {
            ids.append(ids_[i]);
            xs.append(x_[i]);
            ms.append(mass_[i]);
        }
        seenAt_[ids_[i]] = nCouplings_;
    }
    added.ids = ids;
    added.x = xs;
    added.mass = ms;
    ids.clear(); xs.clear(); ms.clear();
    forAll(previousIds_, k)
    {
        if (seenAt_[previousIds_[k]] != nCouplings_)
        {
            ids.append(previousIds_[k]);
            xs.append(previousX_[k]);
            ms.append(previousMass_[k]);
        }
    }
    gone.ids = ids;
    gone.x = xs;
    gone.mass = ms;
}

List<particleInventory::changes> particleInventory::allRanks(const changes& mine)
{
    List<labelList> ids(Pstream::nProcs());
    List<pointField> xs(Pstream::nProcs());
    List<scalarField> ms(Pstream::nProcs());
    const label me = Pstream::myProcNo();
    ids[me] = mine.ids;
    xs[me] = mine.x;
    ms[me] = mine.mass;
    allGather(ids);
    allGather(xs);
    allGather(ms);
    List<changes> all(Pstream::nProcs());
    forAll(all, proci)
    {
        all[proci].ids.transfer(ids[proci]);
        all[proci].x.transfer(xs[proci]);
        all[proci].mass.transfer(ms[proci]);
    }
    return all;
}

bool particleInventory::update(const demParticles& p)
{
    record(p);
    massNow_ = gSum(mass_);
    nNow_ = returnReduce(ids_.size(), sumOp<label>());
    const scalar t = mesh_.time().value();
    changes goneHere, addedHere;
    compare(goneHere, addedHere);   // (at the first coupling every particle is new: not counted)
    previousIds_.transfer(ids_);
    previousX_.transfer(x_);
    previousMass_.transfer(mass_);
    const scalar t0 = previousTime_;
    previousTime_ = t;
    if (nCouplings_++ == 0)
    {
        // the run's first coupling (or a restart's): nothing to compare with yet
        if (massStart_ < 0) massStart_ = massNow_;
        return false;
    }
    if (!returnReduce(goneHere.ids.size() + addedHere.ids.size() > 0, orOp<bool>())) return false;
    const List<changes> gone(allRanks(goneHere)), added(allRanks(addedHere));

    Map<label> arrived;   // new on a rank; those that were gone from another moved between them
    for (const changes& c : added) for (const label id : c.ids) arrived.set(id, 0);
    label nLost = 0, lostId = -1;
    point lostX(Zero);
    bool changed = false;
    for (const changes& c : gone)
    {
        forAll(c.ids, k)
        {
            if (arrived.erase(c.ids[k])) continue;
            const label r = find(outlets_, c.x[k]);
            region& to = r >= 0 ? outlets_[r] : lost_;
            ++to.n;
            to.mass += c.mass[k];
            changed = true;
            if (r < 0 && nLost++ == 0) { lostId = c.ids[k]; lostX = c.x[k]; }
        }
    }
    for (const changes& c : added)
    {
        forAll(c.ids, k)
        {
            if (!arrived.found(c.ids[k])) continue;
            const label r = find(inlets_, c.x[k]);
            region& from = r >= 0 ? inlets_[r] : elsewhere_;
            ++from.n;
            from.mass += c.mass[k];
            changed = true;
        }
    }
    if (nLost > 0 && !allowLoss_) stopOnLoss(nLost, lostId, lostX, t0);
    if (changed) ++nChanged_;
    return changed;
}

void particleInventory::stopOnLoss(label nLost, label id, const point& x, scalar t0) const
{
    FatalErrorInFunction
        << nLost << " particle(s) left the DEM between time " << t0 << " and "
        << mesh_.time().timeName()
        << (outlets_.size() ? " outside every outlet of openSystem in " : ", and there is no outlet (openSystem) in ")
        << dict_.name() << " (the first: particle " << id << ", last seen at " << x << ")" << nl
        << "    LIGGGHTS deletes particles that leave its box: check the DEM walls and time steps;"
        << " if particles are removed there on purpose, add an outlet whose box holds that place"
        << " (openSystem { outlets { <name> { box (x0 y0 z0) (x1 y1 z1); } } }), or set"
        << " allowParticleLoss true" << exit(FatalError);
}

// An outlet through which no particle has left while the particles inside its box grew at each of
// the last two reports: the DEM is likely not removing particles there (warned once per outlet).
void particleInventory::checkPileUp(const demParticles& p)
{
    for (region& r : outlets_)
    {
        label inside = 0;
        for (label i = 0; i < p.size(); ++i)
        {
            if (r.box.contains(point(p.x[3*i], p.x[3*i + 1], p.x[3*i + 2]))) ++inside;
        }
        reduce(inside, sumOp<label>());
        r.growing = (r.inside >= 0 && inside > r.inside) ? r.growing + 1 : 0;
        r.inside = inside;
        if (r.n == 0 && r.growing >= 2 && !r.warned)
        {
            WarningInFunction
                << "outlet openSystem/outlets/" << r.name << " of " << dict_.name() << " has removed no"
                << " particle since the run started, while the particles inside its box " << r.box
                << " grew to " << inside << " at time " << mesh_.time().timeName() << nl
                << "    does the DEM remove particles there (e.g. fix massflow/mesh ... count once"
                << " delete_atoms yes, at a plane inside the box)?" << endl;
            r.warned = true;
        }
    }
}

scalar particleInventory::balance() const
{
    scalar in = elsewhere_.mass, out = lost_.mass;
    for (const region& r : inlets_) in += r.mass;
    for (const region& r : outlets_) out += r.mass;
    return massNow_ > 0 ? (massNow_ - (massStart_ + in - out))/massNow_ : 0;
}

void particleInventory::report(Ostream& os) const
{
    os  << "Particle inventory: " << nNow_ << " particles, " << massNow_ << " kg; since the start: entered";
    for (const region& r : inlets_) os << " " << r.name << " " << r.n << " (" << r.mass << " kg),";
    os  << " elsewhere " << elsewhere_.n << " (" << elsewhere_.mass << " kg); left";
    for (const region& r : outlets_) os << " " << r.name << " " << r.n << " (" << r.mass << " kg),";
    os  << " lost " << lost_.n << " (" << lost_.mass << " kg); mass balance rel. err " << balance() << endl;
}

void particleInventory::write(const demParticles& p)
{
    // a closed system in which nothing has entered or left writes nothing
    if (!open() && nChanged_ == 0 && !tally_) return;
    tally_ = true;
    checkPileUp(p);
    if (Pstream::master() && !file_) openFile();
    if (file_)
    {
        OFstream& f = *file_;
        f << mesh_.time().timeName() << " " << nNow_ << " " << massNow_;
        for (const region& r : inlets_) f << " " << r.n << " " << r.mass;
        f << " " << elsewhere_.n << " " << elsewhere_.mass;
        for (const region& r : outlets_) f << " " << r.n << " " << r.mass;
        f << " " << lost_.n << " " << lost_.mass << " " << balance() << endl;
    }
    // the totals for a restart from this time (every rank holds them: each reads its own copy)
    const fileName dir = mesh_.time().timePath()/"uniform";
    mkDir(dir);
    OFstream f(dir/"particleInventory");
    f.precision(17);   // round-trip: a continued run's mass balance holds to round-off, whatever writePrecision
    f << "massStart " << massStart_ << ";" << nl;
    for (const region& r : inlets_) f << "in_" << r.name << " (" << r.n << " " << r.mass << ");" << nl;
    for (const region& r : outlets_) f << "out_" << r.name << " (" << r.n << " " << r.mass << ");" << nl;
    f << "elsewhere_ (" << elsewhere_.n << " " << elsewhere_.mass << ");" << nl
      << "lost_ (" << lost_.n << " " << lost_.mass << ");" << nl;
}

void particleInventory::readRestart()
{
    const fileName file = mesh_.time().timePath()/"uniform"/"particleInventory";
    if (!isFile(file)) return;
    IFstream is(file);
    const dictionary d(is);
    tally_ = true;
    massStart_ = d.get<scalar>("massStart");
    auto read = [&d](region& r, const word& key)
    {
        if (!d.found(key)) return;   // a region added since: counted from here on
        const scalarList v(d.get<scalarList>(key));
        r.n = label(v[0]);
        r.mass = v[1];
    };
    for (region& r : inlets_) read(r, "in_" + r.name);
    for (region& r : outlets_) read(r, "out_" + r.name);
    read(elsewhere_, "elsewhere_");
    read(lost_, "lost_");
}

} // End namespace Foam
