# exodiff command file of regression/timoshenko_scni (how tolerances are chosen: docs/regression.md).
# Every value: relative 1e-8. The floor F of a variable is its absolute part: values with
# |gold| <= F and |result| <= F are not compared, a value crossing F is; F is therefore the absolute
# tolerance of values near zero. Here F = 1e-3 x the largest value of the field (stress components
# share the stress scale): on 2 ranks this case differs from the 1-rank gold by at most 2.4e-13 x
# that scale (measured per field: displacement 4e-14, stress 1.9e-13, strain 2e-13, reactions
# 2.4e-13), i.e. by <= 2.4e-10 relative at the floor, 40 x below the tolerance.
# Fields that are zero by physics get an absolute tolerance of about 1e-12 x their family's scale.
# "(all)": a variable the file gains later is compared at relative 1e-8 with no floor until it is
# listed here with its own tolerance.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-14

GLOBAL VARIABLES (all) relative 1.e-8 floor 0.0
	strain_energy	relative 1.e-8 floor 0.0	# 4.54; 2-rank difference 8e-14 relative
	R_clamp_x	absolute 5.e-9			# zero by physics (no net axial force): 3e-12 x |R_clamp_y|; 2-rank noise 1.6e-10
	R_clamp_y	relative 1.e-8 floor 1.5	# 1460

NODAL VARIABLES (all) relative 1.e-8 floor 0.0
	displacement_x	relative 1.e-8 floor 9.e-6	# scale 9.03e-3 (tip deflection)
	displacement_y	relative 1.e-8 floor 9.e-6
	stress_xx	relative 1.e-8 floor 1.9		# stress scale 1.90e3
	stress_yy	relative 1.e-8 floor 1.9
	stress_xy	relative 1.e-8 floor 1.9
	stress_zz	absolute 2.e-9			# plane stress: exactly zero; 1e-12 x the stress scale
	strain_xx	relative 1.e-8 floor 6.3e-8	# strain scale 6.33e-5
	strain_yy	relative 1.e-8 floor 6.3e-8
	strain_zz	relative 1.e-8 floor 6.3e-8
	strain_xy	relative 1.e-8 floor 6.3e-8
	von_mises	relative 1.e-8 floor 1.9
