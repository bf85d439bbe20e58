// Smoke test of the in-process DEM: LIGGGHTS as a library, driven the way the coupled solver
// drives it, through fix couple/coarse.
//
//   driver in.smoke            (serial or under mpirun)
//
// The input (in.smoke) makes 81 non-touching spheres under gravity, moving through a periodic
// x boundary. Each coupling cycle the driver pulls the particles, pushes an upward force
// F = m g on the particles with odd ID and none on those with even ID, and runs the DEM.
// Only every second cycle pushes: in the others the stored force must persist, also for
// particles that moved to another rank or were sorted. At the end:
//   - odd IDs  (F = -weight): height and vertical velocity unchanged;
//   - even IDs (no force):    free fall, z = z0 - g t^2 / 2 (exact for velocity Verlet);
//   - total_force() and the fix's global vector equal the sum of pushed forces;
//   - with 2 or more ranks, some forced particles changed rank (so migration was exercised).
// Then a drag phase: every particle gets K (u_f - v) with its current velocity (push_drag) for two
// runs (the first with setup, the second without); coupling_impulse() must equal the particles'
// change of momentum less the weight's impulse (what velocity Verlet actually gave them).
// Last, a new force and a run without setup after begin_segment (the solver's segments): impulse and
// momentum change are exactly F T (without begin_segment they are 4.5 % off).
// Prints PASS/FAIL lines and "N passed, N failed"; exit status 0 only if all passed.

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "lammps.h"
#include "input.h"
#include "modify.h"
#include "fix.h"
#include "fix_couple_coarse.h"

namespace {

const double g = 9.81;
const double z0 = 0.05;
const double dt = 1.0e-5;
const int steps_per_cycle = 200;
const int ncycles = 10;
const int nparticles = 81;

int rank = 0;
int npass = 0, nfail = 0;

void check(bool ok, const std::string &what)
{
    if (ok) npass++; else nfail++;
    if (rank == 0) std::printf("%s: %s\n", ok ? "PASS" : "FAIL", what.c_str());
}

double mass(double r, double rho)
{
    // same expression as LIGGGHTS' "set density" so the weight cancels gravity bit for bit
    return 4.0 * M_PI / 3.0 * r * r * r * rho;
}

struct Particles {
    int n = 0;
    std::vector<double> x, v, r, rho;
    std::vector<int> type;
    std::vector<long long> id;
};

Particles pull(LAMMPS_NS::FixCoupleCoarse *fix)
{
    Particles p;
    p.n = fix->nlocal();
    p.x.resize(3 * p.n); p.v.resize(3 * p.n);
    p.r.resize(p.n); p.rho.resize(p.n); p.type.resize(p.n); p.id.resize(p.n);
    fix->pull(p.x.data(), p.v.data(), p.r.data(), p.rho.data(), p.type.data(), p.id.data());
    return p;
}

// upward force m g on odd IDs, nothing on even IDs; returns the local sum of Fz
double push(LAMMPS_NS::FixCoupleCoarse *fix, const Particles &p)
{
    std::vector<double> f(3 * p.n, 0.0);
    double sum = 0.0;
    for (int i = 0; i < p.n; i++) {
        if (p.id[i] % 2 == 1) {
            f[3 * i + 2] = mass(p.r[i], p.rho[i]) * g;
            sum += f[3 * i + 2];
        }
    }
    fix->push_forces(f.data());
    return sum;
}

// after a run: the particles' total momentum (3) and the impulse the fix counted (3), over all ranks
void momentum_and_impulse(LAMMPS_NS::FixCoupleCoarse *fix, double out[6])
{
    const Particles p = pull(fix);
    double local[6] = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < p.n; i++) {
        const double m = mass(p.r[i], p.rho[i]);
        for (int d = 0; d < 3; d++) local[d] += m * p.v[3 * i + d];
    }
    fix->coupling_impulse(local + 3);
    MPI_Allreduce(local, out, 6, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

}  // namespace

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int nprocs = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
    const char *input = argc > 1 ? argv[1] : "in.smoke";

    char *lmpargv[] = {const_cast<char *>("liggghts"), const_cast<char *>("-screen"),
                       const_cast<char *>("none"), const_cast<char *>("-log"),
                       const_cast<char *>("log.liggghts"), NULL};
    LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(5, lmpargv, MPI_COMM_WORLD);
    lmp->input->file(input);

    int ifix = lmp->modify->find_fix("cpl");
    LAMMPS_NS::FixCoupleCoarse *fix =
        ifix < 0 ? NULL : dynamic_cast<LAMMPS_NS::FixCoupleCoarse *>(lmp->modify->fix[ifix]);
    check(fix != NULL, "fix cpl found through lmp->modify and is a FixCoupleCoarse");
    if (!fix) {
        MPI_Abort(MPI_COMM_WORLD, 1);
    }

    // ---- initial state
    Particles p = pull(fix);
    int ntotal = 0;
    MPI_Allreduce(&p.n, &ntotal, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    check(ntotal == nparticles, "pull() sees all " + std::to_string(nparticles) +
                                " particles (got " + std::to_string(ntotal) + ")");
    std::set<long long> initial_ids(p.id.begin(), p.id.end());

    double pushed_local = push(fix, p), pushed = 0.0;
    MPI_Allreduce(&pushed_local, &pushed, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);

    // ---- coupling cycles: push only every second cycle, the force must persist in between
    char cmd[64];
    for (int c = 0; c < ncycles; c++) {
        std::snprintf(cmd, sizeof(cmd), c == 0 ? "run %d" : "run %d pre no post no",
                      steps_per_cycle);
        lmp->input->one(cmd);
        if (c % 2 == 1 && c + 1 < ncycles) {
            p = pull(fix);
            push(fix, p);
        }
    }

    // ---- checks
    p = pull(fix);
    const double t = ncycles * steps_per_cycle * dt;
    const double zfall = z0 - 0.5 * g * t * t;
    const double vfall = -g * t;
    double err_float = 0.0, err_fall = 0.0, verr_float = 0.0, verr_fall = 0.0;
    int nodd = 0, neven = 0, nmigrated = 0;
    for (int i = 0; i < p.n; i++) {
        const double z = p.x[3 * i + 2], vz = p.v[3 * i + 2];
        if (p.id[i] % 2 == 1) {
            nodd++;
            err_float = std::fmax(err_float, std::fabs(z - z0));
            verr_float = std::fmax(verr_float, std::fabs(vz));
        } else {
            neven++;
            err_fall = std::fmax(err_fall, std::fabs(z - zfall));
            verr_fall = std::fmax(verr_fall, std::fabs(vz - vfall));
        }
        // migrated particles that carry a pushed force (odd IDs) are what this checks
        if (p.id[i] % 2 == 1 && !initial_ids.count(p.id[i])) nmigrated++;
    }
    double loc[4] = {err_float, err_fall, verr_float, verr_fall}, glob[4];
    MPI_Allreduce(loc, glob, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    int iloc[3] = {nodd, neven, nmigrated}, iglob[3];
    MPI_Allreduce(iloc, iglob, 3, MPI_INT, MPI_SUM, MPI_COMM_WORLD);

    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "%d particles with F = -m g float: max |dz| = %.3e m, max |vz| = %.3e m/s",
                  iglob[0], glob[0], glob[2]);
    check(iglob[0] > 0 && glob[0] < 1e-10 && glob[2] < 1e-8, msg);
    std::snprintf(msg, sizeof(msg),
                  "%d particles without force fall %.4f mm as g t^2/2: max error %.3e m, vz error %.3e m/s",
                  iglob[1], (z0 - zfall) * 1e3, glob[1], glob[3]);
    check(iglob[1] > 0 && glob[1] < 1e-9 && glob[3] < 1e-8, msg);

    double tf[3], tf_all[3];
    fix->total_force(tf);
    MPI_Allreduce(tf, tf_all, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    std::snprintf(msg, sizeof(msg), "sum of total_force() = %.6e N equals the pushed %.6e N",
                  tf_all[2], pushed);
    check(std::fabs(tf_all[2] - pushed) <= 1e-12 * std::fabs(pushed) && tf_all[0] == 0.0 &&
              tf_all[1] == 0.0, msg);
    const double fz_vec = fix->compute_vector(2);
    std::snprintf(msg, sizeof(msg), "fix global vector f_cpl[3] = %.6e N equals it", fz_vec);
    check(std::fabs(fz_vec - pushed) <= 1e-12 * std::fabs(pushed), msg);

    if (nprocs > 1) {
        std::snprintf(msg, sizeof(msg),
                      "%d particles with a pushed force changed rank during the run (force followed them)", iglob[2]);
        check(iglob[2] > 0, msg);
    }

    // ---- drag phase: the impulse the fix counts is the momentum the particles got
    {
        const double tau = 2.0e-3;                        // particle response time m/K (s)
        const double uf[3] = {0.2, -0.1, 0.5};            // fluid velocity at every particle (m/s)
        const int nrun = 150;
        std::vector<double> zero(3 * p.n, 0.0), K(p.n), u(3 * p.n);
        double local[4] = {0, 0, 0, 0};                   // momentum before (3), weight (1)
        for (int i = 0; i < p.n; i++) {
            const double m = mass(p.r[i], p.rho[i]);
            K[i] = m / tau;
            for (int d = 0; d < 3; d++) {
                u[3 * i + d] = uf[d];
                local[d] += m * p.v[3 * i + d];
            }
            local[3] += m * g;
        }
        fix->push_forces(zero.data());
        fix->push_drag(K.data(), u.data());
        double before[4];
        MPI_Allreduce(local, before, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
        std::snprintf(cmd, sizeof(cmd), "run %d pre yes post no", nrun);
        lmp->input->one(cmd);
        std::snprintf(cmd, sizeof(cmd), "run %d pre no post no", nrun);
        lmp->input->one(cmd);
        double after[6];
        momentum_and_impulse(fix, after);
        const double T = 2 * nrun * dt;
        double err = 0.0, scale = 0.0;
        for (int d = 0; d < 3; d++) {
            const double got = after[d] - before[d] + (d == 2 ? before[3] * T : 0.0);
            err = std::fmax(err, std::fabs(got - after[3 + d]));
            scale = std::fmax(scale, std::fabs(got));
        }
        std::snprintf(msg, sizeof(msg),
                      "drag K (u_f - v) for 2 x %d DEM steps: coupling_impulse() (%.6e %.6e %.6e) N s"
                      " equals the particles' momentum change less the weight's impulse to %.1e of it",
                      nrun, after[3], after[4], after[5], err / scale);
        check(scale > 0 && err <= 1e-12 * scale, msg);
    }

    // ---- a new force and a segment without LIGGGHTS' setup ("run N pre no", as the solver runs its
    // segments): begin_segment puts the force just pushed into each particle's force, so the first
    // half-kick uses it; the impulse is then exactly F T and the momentum change F T less the
    // weight's. Without it the first half-kick would use the drag phase's last force.
    {
        p = pull(fix);
        const int nrun = 150;
        std::vector<double> f(3 * p.n);
        double local[7] = {0, 0, 0, 0, 0, 0, 0};          // momentum before (3), weight (1), pushed (3)
        const double share[3] = {0.3, -0.2, 0.7};         // of each particle's weight
        for (int i = 0; i < p.n; i++) {
            const double m = mass(p.r[i], p.rho[i]);
            for (int d = 0; d < 3; d++) {
                f[3 * i + d] = share[d] * m * g;
                local[d] += m * p.v[3 * i + d];
                local[4 + d] += f[3 * i + d];
            }
            local[3] += m * g;
        }
        double before[7];
        MPI_Allreduce(local, before, 7, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
        fix->push_forces(f.data());
        fix->begin_segment(nrun, 1, nprocs > 1);
        std::snprintf(cmd, sizeof(cmd), "run %d pre no post no", nrun);
        lmp->input->one(cmd);
        double after[6];
        momentum_and_impulse(fix, after);
        const double T = nrun * dt;
        double err_impulse = 0.0, err_momentum = 0.0, scale = 0.0;
        for (int d = 0; d < 3; d++) {
            const double expected = before[4 + d] * T;
            const double got = after[d] - before[d] + (d == 2 ? before[3] * T : 0.0);
            err_impulse = std::fmax(err_impulse, std::fabs(after[3 + d] - expected));
            err_momentum = std::fmax(err_momentum, std::fabs(got - expected));
            scale = std::fmax(scale, std::fabs(expected));
        }
        std::snprintf(msg, sizeof(msg),
                      "a new force over %d DEM steps without setup (begin_segment): coupling_impulse() and the"
                      " particles' momentum change less the weight's are F T to %.1e and %.1e of it",
                      nrun, err_impulse / scale, err_momentum / scale);
        check(scale > 0 && err_impulse <= 1e-12 * scale && err_momentum <= 1e-12 * scale, msg);
    }

    if (rank == 0) std::printf("liggghts_smoke (np=%d): %d passed, %d failed\n", nprocs, npass, nfail);
    delete lmp;
    MPI_Finalize();
    return nfail == 0 ? 0 : 1;
}
