# baseline: nothing changed (the tutorial's inputs, Zhang et al. 2023 Table II): the study's
# reference, run as the others are (from the shipped state, -mode study). Applied by Allrun
# -ingredient baseline to a case directory ($1).
true
