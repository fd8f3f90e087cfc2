# exodiff command file of an explicit case (how tolerances are chosen: docs/regression.md).
# Every value: relative 1e-8, with a floor of about 1e-6 x the field's scale (values below it are
# compared absolutely): 1000 explicit steps on 2 and 3 ranks differ from one rank by 4e-13 x the
# scale (tests/mpi/ExplicitRanksTest.cpp), far below both.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-12

GLOBAL VARIABLES (all) relative 1.e-8 floor 1.e-9
	u_xmin_y	absolute 1.e-10	# zero by physics
	energy_balance_error	absolute 1.e-8	# a fraction, small
	external_work	relative 1.e-8 floor 1.e-9
	wall_work	relative 1.e-8 floor 1.e-9

NODAL VARIABLES (all) relative 1.e-8 floor 1.e-8
	displacement_x	relative 1.e-8 floor 1.e-8	# scale 1e-2
	displacement_y	absolute 1.e-10		# zero by physics (nu = 0, 1D motion): round-off only
	velocity_x	relative 1.e-8 floor 1.e-6	# scale 1
	velocity_y	absolute 1.e-9		# zero by physics: round-off only
	stress_xx	relative 1.e-8 floor 1.e-6	# scale 1
	stress_yy	absolute 1.e-9		# zero by physics
	stress_zz	absolute 1.e-9		# plane stress: zero
	stress_xy	absolute 1.e-9		# zero by physics
