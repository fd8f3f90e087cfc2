# exodiff command file of regression/timoshenko_perturbed (how tolerances are chosen: docs/regression.md).
# Every value: relative 1e-8. The floor F of a variable is its absolute part: values with
# |gold| <= F and |result| <= F are not compared, a value crossing F is; F is therefore the absolute
# tolerance of values near zero. Here F = 1e-3 x the largest value of the field (stress components
# share the stress scale): on 2 ranks this case differs from the 1-rank gold by at most 5.8e-13 x
# that scale (measured per field: displacement 2.4e-13, stress 5.8e-13 (stress_yy), strain
# 5.6e-13, strain energy 4.7e-13, reactions 1.7e-13), i.e. by <= 5.8e-10 relative at the floor,
# 17 x below the tolerance. The perturbed nodes make this case the noisiest one: a floor of
# 1e-4 x the scale would leave a margin below 2.
# Fields that are zero by physics get an absolute tolerance of about 1e-12 x their family's scale.
# "(all)": a variable the file gains later is compared at relative 1e-8 with no floor until it is
# listed here with its own tolerance.
DEFAULT TOLERANCE relative 1.e-8 floor 0.0
COORDINATES absolute 1.e-12
TIME STEPS absolute 1.e-14

GLOBAL VARIABLES (all) relative 1.e-8 floor 0.0
	strain_energy	relative 1.e-8 floor 0.0	# 4.54
	R_clamp_x	relative 1.e-8 floor 1.2	# 99.5 (not zero on the perturbed nodes); scale 1152
	R_clamp_y	relative 1.e-8 floor 1.2	# 1152

NODAL VARIABLES (all) relative 1.e-8 floor 0.0
	displacement_x	relative 1.e-8 floor 9.e-6	# scale 9.03e-3 (tip deflection)
	displacement_y	relative 1.e-8 floor 9.e-6
	stress_xx	relative 1.e-8 floor 1.9		# stress scale 1.92e3
	stress_yy	relative 1.e-8 floor 1.9
	stress_xy	relative 1.e-8 floor 1.9
	stress_zz	absolute 2.e-9			# plane stress: exactly zero; 1e-12 x the stress scale
	strain_xx	relative 1.e-8 floor 6.4e-8	# strain scale 6.39e-5
	strain_yy	relative 1.e-8 floor 6.4e-8
	strain_zz	relative 1.e-8 floor 6.4e-8
	strain_xy	relative 1.e-8 floor 6.4e-8
	von_mises	relative 1.e-8 floor 1.9
