# exodiff command file of regression/shell_rolled_strip (how tolerances are chosen:
# docs/regression.md). Every value: relative 1e-8 above the field's floor F (values with |gold| and
# |result| <= F are not compared). F = 1e-3 x the field's largest value for the displacements,
# rotations and bending moments; 1e-2 x for the membrane and transverse shear forces and
# moment_xy, which are discretization noise of a pure-bending state (the exact ones are 0) and
# carry the largest 2-rank differences (8e-10 on membrane_force_xx of scale 220). Fields zero by
# symmetry get an absolute tolerance about 100 x their 2-rank noise. Measured 1 vs 2 ranks (per
# field, absolute): displacements 1.1e-12..3.7e-12, rotations 3.4e-13..7.3e-12, membrane forces
# 1.9e-10..7.9e-10, moments 2.2e-12..2.4e-11, shear forces 3.1e-10..3.4e-10.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-14

GLOBAL VARIABLES (all) relative 1.e-8 floor 0.0
	strain_energy	relative 1.e-8 floor 0.17	# 168; 2-rank difference 8.9e-12
	kinetic_energy	absolute 1.e-14			# an implicit stage: 0
	external_work	absolute 1.e-14			# 0 in implicit stages
	probe_tip_ux	relative 1.e-8 floor 0.015	# 14.6
	probe_tip_uy	absolute 1.e-10			# zero by symmetry; noise 2.2e-12
	probe_tip_uz	relative 1.e-8 floor 0.0086	# 8.64
	probe_tip_rx	absolute 1.e-10			# zero by symmetry; noise 5.7e-13
	probe_tip_ry	relative 1.e-8 floor 0.0031	# 3.13
	probe_tip_mxx	relative 1.e-8 floor 0.053	# 53.1 (the applied moment per width, 52.36)
	probe_tip_myy	relative 1.e-8 floor 0.0086	# 0.086; noise 1.2e-12
	probe_tip_mxy	absolute 2.e-9			# zero by symmetry; noise 2.4e-11

NODAL VARIABLES (all) relative 1.e-8 floor 0.0
	displacement_x	relative 1.e-8 floor 0.015	# scale 14.6
	displacement_y	absolute 5.e-10			# 2e-4 (zero for nu = 0 up to discretization); noise 3.7e-12
	displacement_z	relative 1.e-8 floor 0.0086	# scale 8.64
	rotation_x	absolute 1.e-9			# 4e-4 (the frames' rotation; 0.04 with the former director-based output near pi); noise below 1e-9
	rotation_y	relative 1.e-8 floor 0.0031	# scale 3.13
	membrane_force_xx	relative 1.e-8 floor 2.2	# scale 220
	membrane_force_yy	relative 1.e-8 floor 0.43	# scale 43
	membrane_force_xy	relative 1.e-8 floor 1.6	# scale 162
	moment_xx	relative 1.e-8 floor 0.054	# scale 53.6
	moment_yy	relative 1.e-8 floor 0.012	# scale 1.19
	moment_xy	relative 1.e-8 floor 0.008	# scale 0.80; noise 2.4e-11
	shear_force_xz	relative 1.e-8 floor 0.5	# scale 49.8
	shear_force_yz	relative 1.e-8 floor 0.061	# scale 6.1; noise 3.1e-10
