"""From a scene's steps to its motion: the plan (`plan`), the motion given on another
quantity (`given`), the compiler that orders the steps (`compiler`; the mobility and what
the steps leave over: `mobility`; where a scene that cannot assemble could: `reach`), the
motion record (`kinematics`), following the branch over a cycle (`tracking`), the error
bounds (`errorbound`), what follows from a motion (`derived`: rubbing, torque, transmission
angle) and the instantaneous centres (`centres`).

Layers inside, each importing only those below it: derived, errorbound, centres ->
tracking -> kinematics, compiler -> reach, mobility -> completion -> given -> plan."""
