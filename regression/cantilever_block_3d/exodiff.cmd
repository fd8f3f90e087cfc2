# exodiff command file of regression/cantilever_block_3d (how tolerances are chosen: docs/regression.md).
# Every value: relative 1e-8. The floor F of a variable is its absolute part: values with
# |gold| <= F and |result| <= F are not compared, a value crossing F is; F is therefore the absolute
# tolerance of values near zero. Here F = 1e-4 x the largest value of the field (stress components
# share the stress scale): on 2 ranks this case differs from the 1-rank gold by at most 4.1e-14 x
# that scale (measured per field: displacement 3.3e-16, stress 4.1e-14 (stress_zz), von Mises
# 2.9e-14, reactions 1.2e-16), i.e. by <= 4.1e-10 relative at the floor, 24 x below the tolerance.
# Fields that are zero by physics get an absolute tolerance of about 1e-12 x their family's scale.
# "(all)": a variable the file gains later is compared at relative 1e-8 with no floor until it is
# listed here with its own tolerance.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-14

GLOBAL VARIABLES (all) relative 1.e-8 floor 0.0
	strain_energy	relative 1.e-8 floor 0.0	# 6.38
	R_clamp_x	absolute 2.e-10			# zero by physics (tip force along -z only): 1e-12 x |R_clamp_z|; 2-rank noise 7e-14
	R_clamp_y	absolute 2.e-10			# zero by physics: as R_clamp_x
	R_clamp_z	relative 1.e-8 floor 0.023	# 232.6

NODAL VARIABLES (all) relative 1.e-8 floor 0.0
	displacement_x	relative 1.e-8 floor 1.3e-5	# displacement scale 0.128 (tip deflection)
	displacement_y	relative 1.e-8 floor 1.3e-5
	displacement_z	relative 1.e-8 floor 1.3e-5
	stress_xx	relative 1.e-8 floor 0.08	# stress scale 797
	stress_yy	relative 1.e-8 floor 0.08
	stress_zz	relative 1.e-8 floor 0.08
	stress_xy	relative 1.e-8 floor 0.08
	stress_yz	relative 1.e-8 floor 0.08
	stress_zx	relative 1.e-8 floor 0.08
	von_mises	relative 1.e-8 floor 0.067	# 666
	nodal_volume	relative 1.e-12 floor 0.0	# geometry only: the same bits on 1 and 2 ranks
