#!/bin/bash
# bench/tolerance_study.sh -- does a solver tolerance of the Mueller tutorial change a result?
#
# Runs the Mueller demo (tutorials/fluidizedBedMuller -mode demo -np 1: 0.1 s of the bubbling bed)
# once per tolerance of one setting, each in its own copy of the tutorial under
# bench/work/tolerance_<setting>/<tol>/, and compares the depth-averaged, binned profiles (gas fraction
# and particle v_z at the six MR heights) of each with those of the reference tolerance (the first of
# the list). The bed is chaotic: any difference, however small, grows until the runs are different
# samples of the same bed. A tolerance is harmless when its profiles differ from the reference's no
# more than those of a tighter tolerance do.
#
#   bench/tolerance_study.sh -setting diffusion|pressure|velocity|demStep|cfdStep|correctors [-values "REF T2 T3 ..."]
#                            [-name NAME]
#
# Settings:
#   diffusion  diffusionProps tolerance (the smoothing's CG), model diffusion (b = 6 d); stage alphaP.
#              Default values "1e-10 1e-12 1e-6"
#   pressure   the tolerance of p and pFinal in system/fvSolution (GAMG; relTol 0.01 and 0 as the
#              tutorial's), model bigParticle; stage fluid. Default values "1e-8 1e-10 1e-6"
#   velocity   the tolerance of U and UFinal in system/fvSolution (smoothSolver symGaussSeidel, relTol
#              0 as the tutorial's), model bigParticle; stage fluid. Default values "1e-8 1e-10 1e-6"
#   demStep    the DEM step in s (DEM/materials.liggghts timestep), with couplingInterval set so that
#              the CFD step stays 1.8e-4 s; model bigParticle; stage DEM. Default values
#              "3e-6 1.5e-6 6e-6" (9.1, 4.5 and 18.2 % of the Rayleigh time 3.3e-5 s)
#   cfdStep    the CFD step in s: couplingInterval = step / the tutorial's DEM step (1e-5 s), a whole
#              number; model bigParticle; stage fluid. Default values "1.8e-4 9e-5 2.7e-4" (the
#              tutorial's, the paper's CFL 0.5 on the fluid's largest Courant number; half; 1.5 times)
#   correctors nCorrectors of PIMPLE (pressure correctors per step; one outer corrector), model
#              bigParticle; stage fluid. Default values "2 3 1"
# Written: bench/results/tolerance_<setting>.csv (per tolerance, quantity and height: the RMS over the
# profile of its difference from the reference), tolerance_<setting>_timers.csv (the setting's stage
# timer and its share, the time loop's wall seconds, the fluid's largest Courant number and the CFD steps
# above 1, the pressure's iterations and continuity error, of each run) and tolerance_<setting>_info.txt
# (command, commit); with -name NAME, results/NAME*.csv and NAME_info.txt instead, the runs in
# work/NAME/ (another study of a setting kept beside the first).
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
setting= values= name=
while [ $# -gt 0 ]; do
    case "$1" in
        -setting) setting="$2"; shift 2 ;;
        -values) values="$2"; shift 2 ;;
        -name) name="$2"; shift 2 ;;
        *) echo "usage: $0 -setting diffusion|pressure|velocity|demStep|cfdStep|correctors [-values \"REF T2 T3 ...\"] [-name NAME]" >&2; exit 2 ;;
    esac
done
case "$setting" in
    diffusion) model=diffusion stage=alphaP; values=${values:-"1e-10 1e-12 1e-6"} ;;
    pressure) model=bigParticle stage=fluid; values=${values:-"1e-8 1e-10 1e-6"} ;;
    velocity) model=bigParticle stage=fluid; values=${values:-"1e-8 1e-10 1e-6"} ;;
    demStep) model=bigParticle stage=DEM; values=${values:-"3e-6 1.5e-6 6e-6"} ;;
    cfdStep) model=bigParticle stage=fluid; values=${values:-"1.8e-4 9e-5 2.7e-4"} ;;
    correctors) model=bigParticle stage=fluid; values=${values:-"2 3 1"} ;;
    *) echo "bench/tolerance_study: -setting must be diffusion, pressure, velocity, demStep, cfdStep or correctors (got '$setting')" >&2; exit 2 ;;
esac
for t in $values; do
    if [ "$setting" = correctors ]; then
        [[ "$t" =~ ^[1-9]$ ]] || { echo "bench/tolerance_study: nCorrectors '$t' must be a whole number 1-9" >&2; exit 2; }
    else
        /usr/bin/python3 -c "import sys; t = float(sys.argv[1]); sys.exit(0 if 0 < t < 1 else 1)" "$t" 2> /dev/null ||
            { echo "bench/tolerance_study: tolerance '$t' must be a number in (0, 1)" >&2; exit 2; }
    fi
done
# couplingInterval for a CFD step of S s with the DEM step D s: S / D, refused unless a whole number
steps_per() { # S D what
    /usr/bin/python3 -c "import sys; n = float(sys.argv[1]) / float(sys.argv[2]); sys.exit(1) if abs(n - round(n)) > 1e-9 * n else print(round(n))" "$1" "$2" ||
        { echo "bench/tolerance_study: $3" >&2; return 1; }
}
# the case files of one tolerance, in a copy of the tutorial
set_tolerance() { # tutorial-copy tol
    case "$setting" in
        diffusion) sed -i "s|^diffusionProps .*|diffusionProps      { bandwidth 7.2e-3; tolerance $2; }   // b = 6 d|" \
                       "$1/constant/couplingProperties" ;;
        pressure) sed -i "s|^\( *p  *{ solver GAMG; smoother GaussSeidel; tolerance \)[^;]*;|\1$2;|" "$1/system/fvSolution"
                  grep -q "tolerance $2; relTol 0.01" "$1/system/fvSolution" ||
                      { echo "bench/tolerance_study: the p entry of $1/system/fvSolution is not the one this script edits" >&2; return 1; } ;;
        velocity) sed -i "s#^\( *\"(U|UFinal)\" *{ solver smoothSolver; smoother symGaussSeidel; tolerance \)[^;]*;#\1$2;#" "$1/system/fvSolution"
                  grep -q "symGaussSeidel; tolerance $2; relTol 0;" "$1/system/fvSolution" ||
                      { echo "bench/tolerance_study: the U entry of $1/system/fvSolution is not the one this script edits" >&2; return 1; } ;;
        demStep)
            # the CFD step 1.8e-4 s kept: couplingInterval = 1.8e-4 / step, a whole number
            local n
            n=$(steps_per 1.8e-4 "$2" "DEM step $2 does not divide the CFD step 1.8e-4 s") || return 1
            sed -i "s|^timestep .*|timestep        $2|" "$1/DEM/materials.liggghts"
            sed -i "s|^couplingInterval .*|couplingInterval    $n;|" "$1/constant/couplingProperties"
            grep -q "^timestep        $2" "$1/DEM/materials.liggghts" ||
                { echo "bench/tolerance_study: no timestep line in $1/DEM/materials.liggghts" >&2; return 1; } ;;
        cfdStep)
            # the DEM step kept (the tutorial's), the coupling interval made to give the CFD step
            local n dem
            dem=$(awk '/^timestep/ {print $2}' "$1/DEM/materials.liggghts")
            [ -n "$dem" ] || { echo "bench/tolerance_study: no timestep line in $1/DEM/materials.liggghts" >&2; return 1; }
            n=$(steps_per "$2" "$dem" "CFD step $2 is not a whole number of DEM steps ($dem s)") || return 1
            grep -q "^couplingInterval " "$1/constant/couplingProperties" ||
                { echo "bench/tolerance_study: no couplingInterval line in $1/constant/couplingProperties" >&2; return 1; }
            sed -i "s|^couplingInterval .*|couplingInterval    $n;|" "$1/constant/couplingProperties" ;;
        correctors)
            [ "$(grep -c "^ *nCorrectors  *[0-9]*;" "$1/system/fvSolution")" = 1 ] ||
                { echo "bench/tolerance_study: not one nCorrectors entry in $1/system/fvSolution" >&2; return 1; }
            sed -i "s|^\( *nCorrectors  *\)[0-9]*;|\1$2;|" "$1/system/fvSolution" ;;
    esac
}
name=${name:-tolerance_$setting}
[[ "$name" =~ ^[A-Za-z0-9_]+$ ]] || { echo "bench/tolerance_study: -name must be letters, digits and _ (got '$name')" >&2; exit 2; }
work="$here/work/$name"
mkdir -p "$work" "$here/results"
for t in $values; do
    d="$work/$t"
    rm -rf "$d"
    mkdir -p "$d/tutorials"
    cp -r "$root/tutorials/fluidizedBedMuller" "$d/tutorials/"
    rm -rf "$d/tutorials/fluidizedBedMuller/runs"
    set_tolerance "$d/tutorials/fluidizedBedMuller" "$t" || exit 1
    echo "bench/tolerance_study: $setting tolerance $t"
    ( cd "$d/tutorials/fluidizedBedMuller" &&
      COARSEDEM_DIR="$root" ./Allrun -mode demo -model "$model" -np 1 > "$d/log.Allrun" 2>&1 ) ||
        { echo "bench/tolerance_study: the demo failed with $setting tolerance $t ($d/log.Allrun)" >&2; exit 1; }
done
out="$here/results/$name"
# shellcheck disable=SC2086
/usr/bin/python3 "$here/tolerance_study.py" "$work" "${model}_dx1_U0.9_demo" "$stage" "$out" $values || exit 1
{
    echo "command: bench/tolerance_study.sh -setting $setting -values \"$values\" -name $name"
    echo "commit: $("$root/etc/codeVersion")"
    echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "${out}_info.txt"
cat "$out.csv" "${out}_timers.csv"
