/* props_index.h -- PROPS entries by name for the C harnesses, generated from src/props by
 * `INTERFACIAL_BLESS=1 cargo test --test props_index_files`: do not edit.
 * IFLP_<LAW>_<KEY> is the 0-based offset in a C array of PROPS(i) = props[i - 1];
 * IFLP_<LAW>_NPROPS the length of the whole layout; IFLP_LAW_<LAW> the law code, the
 * value of PROPS(1). The twin of fortran_tests/props_index.inc. */
#ifndef INTERFACIAL_PROPS_INDEX_H
#define INTERFACIAL_PROPS_INDEX_H

/* law 1: the Coulomb law */
#define IFLP_LAW_COULOMB 1
#define IFLP_COULOMB_NPROPS 20
#define IFLP_COULOMB_CODE 0 /* PROPS(1): law code */
#define IFLP_COULOMB_MU 1 /* PROPS(2): friction coefficient */
#define IFLP_COULOMB_MU2 2 /* PROPS(3): second-direction coefficient */
#define IFLP_COULOMB_TAU_MAX 3 /* PROPS(4): shear stress limit */
#define IFLP_COULOMB_GAMMA_CRIT 4 /* PROPS(5): allowable elastic slip */
#define IFLP_COULOMB_SLIP_TOLERANCE 5 /* PROPS(6): slip tolerance */
#define IFLP_COULOMB_STICK 6 /* PROPS(7): stick mode */
#define IFLP_COULOMB_MU_LAW 7 /* PROPS(8): μ law */
#define IFLP_COULOMB_MU_K 8 /* PROPS(9): kinetic coefficient (direction 1) of the decay law */
#define IFLP_COULOMB_DECAY 9 /* PROPS(10): decay coefficient */
#define IFLP_COULOMB_P_REF 10 /* PROPS(11): reference pressure of μ */
#define IFLP_COULOMB_B_THETA 11 /* PROPS(12): temperature coefficient of μ */
#define IFLP_COULOMB_THETA_REF 12 /* PROPS(13): reference temperature of `PROPS(12)` */
#define IFLP_COULOMB_HHT_ALPHA 13 /* PROPS(14): HHT α */
#define IFLP_COULOMB_HHT_BETA 14 /* PROPS(15): HHT β */
#define IFLP_COULOMB_HHT_GAMMA 15 /* PROPS(16): HHT γ */
#define IFLP_COULOMB_DAMPING 16 /* PROPS(17): tangential damping coefficient at zero overclosure */
#define IFLP_COULOMB_DAMPING_CLEARANCE 17 /* PROPS(18): clearance at which the damping coefficient vanishes */
#define IFLP_COULOMB_DAMPING_FRACTION 18 /* PROPS(19): damping plateau fraction */
#define IFLP_COULOMB_FROZEN 19 /* PROPS(20): slip rate of μ */
#define IFLP_COULOMB_OMEGA 13 /* PROPS(14): angular spinning velocity of steady-state transport */
#define IFLP_COULOMB_AXIS 14 /* PROPS(15): spinning axis through the origin */
#define IFLP_COULOMB_VISCOUS_REFERENCE 15 /* PROPS(16): allowable viscous slip rate */
#define IFLP_COULOMB_STICK_STIFFNESS 4 /* PROPS(5): constant stick stiffness */

/* law 2: the adhesive law */
#define IFLP_LAW_ADHESIVE 2
#define IFLP_ADHESIVE_NPROPS 13
#define IFLP_ADHESIVE_CODE 0 /* PROPS(1): law code */
#define IFLP_ADHESIVE_COEFF 1 /* PROPS(2): dynamic friction coefficient */
#define IFLP_ADHESIVE_COEFFSTATIC 2 /* PROPS(3): static friction coefficient */
#define IFLP_ADHESIVE_SA 3 /* PROPS(4): shear adhesive strength */
#define IFLP_ADHESIVE_NA 4 /* PROPS(5): normal adhesive strength */
#define IFLP_ADHESIVE_KMU 5 /* PROPS(6): slope of μ against the slip rate */
#define IFLP_ADHESIVE_VHALF 6 /* PROPS(7): slip rate at which μ_s → μ_d is half done */
#define IFLP_ADHESIVE_GAMMA_CRIT 7 /* PROPS(8): allowable elastic slip */
#define IFLP_ADHESIVE_SLIP_TOLERANCE 8 /* PROPS(9): slip tolerance */
#define IFLP_ADHESIVE_NORMAL_STIFFNESS 9 /* PROPS(10): penalty normal stiffness */
#define IFLP_ADHESIVE_CONDUCTANCE 10 /* PROPS(11): heat conduction across the interface */
#define IFLP_ADHESIVE_HEAT_FRACTION 11 /* PROPS(12): fraction of the frictional dissipation converted into heat */
#define IFLP_ADHESIVE_SLAVE_FRACTION 12 /* PROPS(13): part of that heat flowing into the slave surface, 1 − f into the master */

/* law 3: the rate-and-state law */
#define IFLP_LAW_RATE_STATE 3
#define IFLP_RATE_STATE_NPROPS 11
#define IFLP_RATE_STATE_CODE 0 /* PROPS(1): law code */
#define IFLP_RATE_STATE_MU0 1 /* PROPS(2): steady-state friction coefficient at V₀ */
#define IFLP_RATE_STATE_A 2 /* PROPS(3): direct-effect coefficient */
#define IFLP_RATE_STATE_B 3 /* PROPS(4): evolution-effect coefficient */
#define IFLP_RATE_STATE_V0 4 /* PROPS(5): reference slip rate */
#define IFLP_RATE_STATE_L 5 /* PROPS(6): characteristic slip distance of the state evolution */
#define IFLP_RATE_STATE_EVOLUTION 6 /* PROPS(7): state evolution law */
#define IFLP_RATE_STATE_FORM 7 /* PROPS(8): expression of μ */
#define IFLP_RATE_STATE_GAMMA_CRIT 8 /* PROPS(9): allowable elastic slip */
#define IFLP_RATE_STATE_SLIP_TOLERANCE 9 /* PROPS(10): slip tolerance */
#define IFLP_RATE_STATE_THETA0 10 /* PROPS(11): initial state θ (read when `STATEV(4)` = 0) */

#endif
