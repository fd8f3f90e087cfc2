# exodiff command file of regression/neo_hookean_stretch (how tolerances are chosen: docs/regression.md).
# Every value: relative 1e-8. The floor F of a variable is its absolute part: values with
# |gold| <= F and |result| <= F are not compared, a value crossing F is; F is therefore the absolute
# tolerance of values near zero. Here F = 1e-5 x the largest value of the field: on 2 ranks this
# case differs from the 1-rank gold by at most 1.6e-15 x that scale (measured per field:
# displacement 6.7e-16, stress_xx 1.6e-15, strain 8.6e-16, reactions 5.5e-16), i.e. by
# <= 1.6e-10 relative at the floor, 60 x below the tolerance.
# The stretch is homogeneous and uniaxial: the shear and lateral stresses, the shear strains and
# the reactions other than R_symmetry_x_x and R_pull_x are zero by physics (round-off, <= 6e-15):
# they get an absolute tolerance of 1e-12 x their family's scale.
# "(all)": a variable the file gains later is compared at relative 1e-8 with no floor until it is
# listed here with its own tolerance.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-14

GLOBAL VARIABLES (all) relative 1.e-8 floor 0.0
	strain_energy	relative 1.e-8 floor 0.0	# up to 3.61
	R_symmetry_x_x	relative 1.e-8 floor 6.5e-5	# reaction scale 6.47
	R_pull_x	relative 1.e-8 floor 6.5e-5
	R_symmetry_x_y	absolute 6.5e-12		# zero by physics; 2-rank noise <= 1.5e-15
	R_symmetry_x_z	absolute 6.5e-12
	R_symmetry_y_x	absolute 6.5e-12
	R_symmetry_y_y	absolute 6.5e-12
	R_symmetry_y_z	absolute 6.5e-12
	R_symmetry_z_x	absolute 6.5e-12
	R_symmetry_z_y	absolute 6.5e-12
	R_symmetry_z_z	absolute 6.5e-12
	R_pull_y	absolute 6.5e-12
	R_pull_z	absolute 6.5e-12

NODAL VARIABLES (all) relative 1.e-8 floor 0.0
	displacement_x	relative 1.e-8 floor 1.e-5	# displacement scale 1 (the pull)
	displacement_y	relative 1.e-8 floor 1.e-5
	displacement_z	relative 1.e-8 floor 1.e-5
	stress_xx	relative 1.e-8 floor 1.e-4	# stress scale 10.15
	stress_yy	absolute 1.e-11			# zero by physics; 2-rank noise <= 5.7e-15
	stress_zz	absolute 1.e-11
	stress_xy	absolute 1.e-11
	stress_yz	absolute 1.e-11
	stress_zx	absolute 1.e-11
	strain_xx	relative 1.e-8 floor 1.5e-5	# strain scale 1.5
	strain_yy	relative 1.e-8 floor 1.5e-5
	strain_zz	relative 1.e-8 floor 1.5e-5
	strain_xy	absolute 1.5e-12		# zero by physics; 2-rank noise <= 2.5e-15
	strain_yz	absolute 1.5e-12
	strain_zx	absolute 1.5e-12
	von_mises	relative 1.e-8 floor 1.e-4	# 10.15
