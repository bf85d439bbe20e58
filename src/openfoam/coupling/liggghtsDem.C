#include "liggghtsDem.H"
#include "demScriptHistory.H"
#include "Time.H"
#include "OSspecific.H"
#include "Pstream.H"

#include <mpi.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "lammps.h"
#include "atom.h"
#include "input.h"
#include "modify.h"
#include "fix.h"
#include "update.h"
#include "fix_couple_coarse.h"

// LIGGGHTS stops on an input or run error with exit(1) (Error::all), after writing the message to
// its log only (its screen output is off): without this the solver's output would just end. An
// exit during a LIGGGHTS call is reported on the solver's error output, with the message and a
// hint for the mistakes users make most.
namespace
{
std::string demLogFile;
bool inDemCall = false;
int demRank = 0;   // LIGGGHTS' Error::all stops every rank: the first says so

struct demCall
{
    demCall() { inDemCall = true; }
    ~demCall() { inDemCall = false; }
};

const char* demErrorHint(const std::string& msg)
{
    if (msg.find("processors") != std::string::npos)
        return "the DEM script's processors command must give as many ranks as mpirun -np, split as"
               " system/decomposeParDict splits the mesh (e.g. processors * 1 1 with simple (N 1 1))";
    if (msg.find("Atom types must start from 1") != std::string::npos)
        return "the DEM has no particles: create or read them before the coupling fix";
    if (msg.find("Invalid") != std::string::npos && msg.find("style") != std::string::npos)
        return "a style LIGGGHTS does not know: check its spelling (this LIGGGHTS has no VTK dumps)";
    if (msg.find("Cannot open") != std::string::npos)
        return "a file the DEM script reads is missing; relative paths are relative to the case directory";
    return nullptr;
}

void reportDemExit()
{
    if (!inDemCall || demRank != 0) return;
    std::ifstream log(demLogFile);
    std::string line, last;
    while (std::getline(log, line))
    {
        if (line.compare(0, 5, "ERROR") == 0) last = line;
    }
    const char* hint = demErrorHint(last);
    std::fprintf
    (
        stderr, "\n--> FOAM FATAL ERROR: the DEM (LIGGGHTS) stopped the run\n    %s\n%s%s%s    LIGGGHTS log: %s\n\n",
        last.empty() ? "(no ERROR line in its log)" : last.c_str(),
        hint ? "    " : "", hint ? hint : "", hint ? "\n" : "", demLogFile.c_str()
    );
}
}

// The folders the DEM script writes into (dump files, fix print/ave/time ... file F), checked before
// LIGGGHTS runs it: a missing one stops LIGGGHTS with only MPI_ABORT's banner and an empty log. Reads
// the script and the files it includes by a literal path; paths built from variables are left to
// LIGGGHTS.
namespace Foam
{
static void checkOutputFolders
(
    const fileName& caseDir, const fileName& script, int depth = 0
)
{
    std::ifstream in(script);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::string::size_type hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string t; words >> t;) w.push_back(t);
        if (w.empty()) continue;
        std::vector<std::string> outputs;
        if (w[0] == "dump" && w.size() >= 6) outputs.push_back(w[5]);
        for (size_t i = 0; i + 1 < w.size(); ++i)
        {
            if (w[i] == "file") outputs.push_back(w[i + 1]);
        }
        if (w[0] == "include" && w.size() >= 2 && depth < 5 && w[1].find('$') == std::string::npos
         && isFile(caseDir/w[1]))
        {
            checkOutputFolders(caseDir, caseDir/w[1], depth + 1);
        }
        for (const std::string& out : outputs)
        {
            if (out.find('$') != std::string::npos || out.find('{') != std::string::npos) continue;
            const fileName folder = fileName(out).path();
            if (folder.empty() || folder == "." || isDir(folder.isAbsolute() ? folder : caseDir/folder)) continue;
            FatalErrorInFunction
                << "the DEM script " << script << " (line " << lineNo << ") writes " << out.c_str()
                << ", but its folder " << folder.c_str() << " does not exist in the case " << caseDir
                << " (LIGGGHTS would stop with no message)" << nl
                << "    create it (mkdir -p " << folder.c_str() << " in the case) or write elsewhere"
                << exit(FatalError);
        }
    }
}
}

Foam::liggghtsDem::liggghtsDem(const fvMesh& mesh, const dictionary& dict)
:
    lmp_(nullptr),
    fix_(nullptr),
    restarted_(false),
    ownsMpi_(false),
    needsSetup_(true)
{
    // the DEM script and its relative paths belong to the case, not to processorN/
    const fileName caseDir = mesh.time().globalPath();
    const fileName script = caseDir/dict.get<fileName>("demScript");
    const word fixId = dict.lookupOrDefault<word>("demCouplingFix", "cfd");
    if (!isFile(script))
    {
        FatalIOErrorInFunction(dict)
            << "entry demScript in " << dict.name() << ": DEM input script " << script
            << " not found" << exit(FatalIOError);
    }
    checkOutputFolders(caseDir, script);

    // OpenFOAM starts MPI only for -parallel; LIGGGHTS needs it in every case.
    int started = 0;
    MPI_Initialized(&started);
    if (!started)
    {
        MPI_Init(nullptr, nullptr);
        ownsMpi_ = true;
    }

    const std::string logFile = (caseDir/"log.liggghts");
    demLogFile = logFile;
    MPI_Comm_rank(MPI_COMM_WORLD, &demRank);
    std::atexit(reportDemExit);
    // A restarted run continues the DEM from <startTime>/dem.restart: the script gets
    // ${restarting} (1 or 0) and ${restart} (the file, or "none") and chooses what to read, e.g.
    //   if "${restarting} == 1" then "read_restart ${restart}" else "read_restart DEM/init.restart"
    const fileName restartFile = caseDir/mesh.time().timeName()/"dem.restart";
    const std::string restart = isFile(restartFile) ? std::string(restartFile) : std::string("none");
    restarted_ = restart != "none";
    // A fluid starting after t = 0 without the DEM state of that time would meet particles from the
    // script's initial state: an inconsistent restart, stopped unless asked for (demFreshStart).
    if (!restarted_ && mesh.time().value() > 0 && !dict.lookupOrDefault<Switch>("demFreshStart", false))
    {
        FatalIOErrorInFunction(dict)
            << "the fluid starts at time " << mesh.time().timeName() << " but there is no DEM restart file "
            << restartFile << " (written at write times when demRestart is on)" << nl
            << "    restart from a time that has one, or set demFreshStart true in " << dict.name()
            << " to start the DEM from its script's initial state" << exit(FatalIOError);
    }
    // COARSEDEM_DEM_SCREEN=1 keeps LIGGGHTS' screen output on stdout (for debugging DEM errors)
    std::vector<std::string> args =
        {"liggghts", "-log", logFile, "-var", "restart", restart, "-var", "restarting", restart == "none" ? "0" : "1"};
    if (getEnv("COARSEDEM_DEM_SCREEN").empty())
    {
        // /dev/null, not "none": parts of LIGGGHTS (the STL reader of fix mesh/surface) print to the
        // screen without checking that there is one, and crash when it is off
        args.insert(args.begin() + 1, {"-screen", "/dev/null"});
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(&a[0]);
    lmp_ = new LAMMPS_NS::LAMMPS(int(argv.size()), argv.data(), MPI_COMM_WORLD);

    // Relative paths in the script (data files, dumps) are relative to the case.
    Info<< "DEM restart file: " << restart << nl;
    Info<< "Reading DEM script " << script << " (LIGGGHTS log: " << logFile
        << ")" << endl;
    // a continued run appends to the script's fix print files (demScriptHistory.H): it reads a copy
    // of the script with `file` turned into `append` there, written next to the case's log
    fileName readScript = script;
    if (restarted_)
    {
        std::ifstream in(script);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        label nAppend = 0;
        const std::string appending = appendingHistory(text, nAppend);
        if (nAppend > 0)
        {
            readScript = caseDir/(".continued." + script.name());
            if (Pstream::master()) std::ofstream(readScript) << appending;
            MPI_Barrier(MPI_COMM_WORLD);
            Info<< "Continued run: the DEM script's " << nAppend << " fix print file(s) are appended to" << endl;
        }
    }
    const fileName cwd0 = cwd();
    chDir(caseDir);
    {
        demCall guard;
        lmp_->input->file(readScript.c_str());
    }
    chDir(cwd0);
    if (readScript != script)
    {
        MPI_Barrier(MPI_COMM_WORLD);
        if (Pstream::master()) rm(readScript);
    }
    if (restarted_) checkRestartRead(restartFile, dict);

    const int ifix = lmp_->modify->find_fix(fixId.c_str());
    fix_ = ifix < 0 ? nullptr : dynamic_cast<LAMMPS_NS::FixCoupleCoarse*>(lmp_->modify->fix[ifix]);
    if (!fix_)
    {
        // a couple/coarse fix under another ID: name it, so that the remedy is one entry
        word other;
        for (int i = 0; i < lmp_->modify->nfix && other.empty(); ++i)
        {
            if (dynamic_cast<LAMMPS_NS::FixCoupleCoarse*>(lmp_->modify->fix[i])) other = lmp_->modify->fix[i]->id;
        }
        if (!other.empty())
        {
            FatalErrorInFunction
                << "the DEM script " << script << " defines its couple/coarse fix with ID '" << other
                << "', not '" << fixId << "' (demCouplingFix in " << dict.name() << ")" << nl
                << "    set  demCouplingFix " << other << ";  in " << dict.name() << ", or rename the fix"
                << exit(FatalError);
        }
        FatalErrorInFunction
            << "the DEM script " << script << " defines no fix '" << fixId << "' of style couple/coarse" << nl
            << "    add:  fix " << fixId << " all couple/coarse   (or set demCouplingFix in "
            << dict.name() << ")" << exit(FatalError);
    }
}

// A script that does not read ${restart} when ${restarting} is 1 (one written for fresh starts only)
// would start the DEM again from its initial state under a fluid that continues: the DEM step after
// the script must be the one the restart file was written at (writeRestart keeps it beside the file).
void Foam::liggghtsDem::checkRestartRead(const fileName& restartFile, const dictionary& dict) const
{
    const fileName stepFile = restartFile + ".step";
    long long written = -1;
    if (isFile(stepFile))
    {
        std::ifstream in(stepFile);
        in >> written;
    }
    const long long now = lmp_->update->ntimestep;
    // without the step file (a restart written before it existed) a fresh script is still at step 0
    if (written >= 0 ? now != written : now == 0)
    {
        FatalErrorInFunction
            << "the DEM continues from " << restartFile << " (written at DEM step "
            << (written >= 0 ? std::to_string(written) : std::string("unknown")).c_str() << ") but after its script "
            << dict.get<fileName>("demScript") << " the DEM is at step " << std::to_string(now).c_str()
            << ": the script does not read the restart file" << nl
            << "    read it when the run continues, e.g." << nl
            << "        if \"${restarting} == 1\" then \"read_restart ${restart}\" else \"create_box ...\" \"create_atoms ...\"" << nl
            << "    (tutorials/ErgunTest/DEM), or set demFreshStart true in " << dict.name()
            << " and remove the restart file to start the DEM from its initial state" << exit(FatalError);
    }
}

Foam::liggghtsDem::~liggghtsDem()
{
    delete lmp_;
    // MPI started here (a serial run) ends here: OpenFOAM's exit would finalise it with the warning
    // "Finalizing MPI, but was initialized elsewhere" at the end of every serial run
    if (ownsMpi_)
    {
        MPI_Finalize();
    }
}

Foam::scalar Foam::liggghtsDem::timestep() const
{
    return lmp_->update->dt;
}

void Foam::liggghtsDem::command(const std::string& line)
{
    demCall guard;
    lmp_->input->one(line.c_str());
    needsSetup_ = true;
}

bool Foam::liggghtsDem::deleteMarkedParticles()
{
    // fix massflow/mesh ... delete_atoms yes marks the particles that crossed its surface and deletes
    // them in its pre_exchange, which LIGGGHTS calls only where a run rebuilds its neighbour lists, and
    // a setup's rebuild does not call it: the deletion is called here, between segments, and a
    // deletion makes the next segment start with a setup that rebuilds the lists without them.
    // (No-op when nothing is marked.)
    LAMMPS_NS::Modify& modify = *lmp_->modify;
    demCall guard;
    const int before = lmp_->atom->nlocal;
    for (int i = 0; i < modify.nfix; ++i)
    {
        if (std::string(modify.fix[i]->style).compare(0, 13, "massflow/mesh") == 0) modify.fix[i]->pre_exchange();
    }
    return returnReduce(lmp_->atom->nlocal != before, orOp<bool>());
}

bool Foam::liggghtsDem::forceOverwritingFix() const
{
    const LAMMPS_NS::Modify& modify = *lmp_->modify;
    bool after = false;   // a fix defined after couple/coarse (post_force runs in definition order)
    for (int i = 0; i < modify.nfix; ++i)
    {
        if (modify.fix[i] == fix_) { after = true; continue; }
        const std::string style(modify.fix[i]->style);
        if (after && (style == "setforce" || style == "freeze" || style == "aveforce")) return true;
    }
    return false;
}

void Foam::liggghtsDem::run(label nSteps)
{
    // A segment continues the DEM's last step ("run N pre no": velocity Verlet as in one long
    // LIGGGHTS run), with the coupling force in each particle's force replaced by the one just
    // pushed (begin_segment: the first half-kick uses it, as LIGGGHTS' setup would make it).
    // LIGGGHTS' setup (a neighbour-list build and a whole force evaluation; a fifth of the Mueller
    // demo's DEM stage serially, bench/cases/README.md) runs only after something else changed the
    // DEM: the first segment, a command, a restart written, particles deleted (their neighbour lists
    // are stale), and always when a fix overwrites the forces after the coupling's (the refresh
    // would add the coupling force to a force that fix had set).
    const bool deleted = deleteMarkedParticles();
    const bool setup = needsSetup_ || deleted || forceOverwritingFix();
    // In parallel LIGGGHTS moves a particle to the rank of its new sub-domain only when it rebuilds
    // its neighbour lists; until then a particle that crossed the processor plane is still held by
    // the old rank, outside that rank's part of the CFD mesh. The segment's last step rebuilds them
    // (migrate), so that every particle is pulled by its owner.
    {
        demCall guard;
        fix_->begin_segment(nSteps, !setup, Pstream::parRun());
        lmp_->input->one(("run " + std::to_string(nSteps) + (setup ? " pre yes" : " pre no") + " post no").c_str());
    }
    needsSetup_ = false;
}

void Foam::liggghtsDem::writeRestart(const std::string& file)
{
    // LIGGGHTS re-initialises and re-exchanges the atoms for it; the next run's setup rebuilds the rest
    command("write_restart " + file);
    // the DEM step it holds, to check that a continued run's script reads it (checkRestartRead)
    if (Pstream::master())
    {
        std::ofstream(file + ".step") << lmp_->update->ntimestep << std::endl;
    }
}

void Foam::liggghtsDem::pull(demParticles& p) const
{
    const int n = fix_->nlocal();
    p.x.resize(3*n);
    p.v.resize(3*n);
    p.radius.resize(n);
    p.density.resize(n);
    p.type.resize(n);
    p.id.resize(n);
    fix_->pull(p.x.data(), p.v.data(), p.radius.data(), p.density.data(), p.type.data(), p.id.data());
}

void Foam::liggghtsDem::push(const std::vector<double>& f)
{
    fix_->push_forces(f.data());
}

void Foam::liggghtsDem::pushDrag(const std::vector<double>& K, const std::vector<double>& uf)
{
    fix_->push_drag(K.data(), uf.data());
}

Foam::vector Foam::liggghtsDem::couplingImpulse() const
{
    double j[3];
    fix_->coupling_impulse(j);
    return vector(j[0], j[1], j[2]);
}
