# 1D linear site response of a uniform soil layer, built the way OpenSees site-response scripts are
# (McGann & Arduino's "site response analysis of a layered soil column" pattern), in fem_tcl:
#   - a column one SSPquad wide, n elements high, kN-m-s units (kPa, Mg/m3);
#   - periodic sides: equalDOF between the left and right node of every row (dofs 1 2);
#   - compliant base (default): a Lysmer-Kuhlemeyer dashpot, zeroLength + uniaxialMaterial Viscous with
#     C = rho_r Vs_r A, between a fixed dummy node and the base, and the Joyner & Chen (1975) input force
#     F(t) = rho_r Vs_r A v_outcrop(t) at the base node (pattern Plain with a Path series);
#   - rigid base (-base rigid): base nodes fixed, pattern UniformExcitation with the outcrop acceleration;
#   - optional Rayleigh damping (-damping xi, matched at the first and third mode); the dashpot keeps
#     zeroLength's default -doRayleigh 0 (no Rayleigh damping on the boundary).
# The input is a Ricker wavelet of central frequency f0 centred at t0 (velocity for the compliant base,
# acceleration for the rigid base), of peak -amp (m/s or m/s2).
# Soil: -material elastic (ElasticIsotropic, default) or pimy (PressureIndependMultiYield clay with the same
# G and K, cohesi -su kPa, peakShearStra -gmax, 20 surfaces; plastic from the start, Newton iterations).
# Sample run: build/bin/fem_tcl scripts/site_response/soil_column.tcl /tmp/column -base compliant
# Files in <outdir>: surface_vel.out, surface_accel.out, base_vel.out (`-time`, dof 1 of the left surface /
# base node; relative to the ground for the rigid base), input.out (time, input value), dashpot_force.out
# and dashpot_deformation.out (`-time`, zeroLength force P1_1 P1_2 P2_1 P2_2, deformation), base_stress.out
# (`-time`, the lowest element's stress response: sxx syy sxy, or with pimy sxx syy szz sxy ratio), model.json
# (print -JSON).
set outdir [lindex $argv 0]
if {$outdir eq ""} { error "usage: soil_column.tcl outdir ?-base compliant|rigid? ?-H 25? ?-n 50? ?-Vs 100? ?-rho 2.0? ?-nu 0.3? ?-Vr 160? ?-rhor 2.5? ?-damping 0? ?-f0 3? ?-t0 0.5? ?-tend 4? ?-dt 0.001? ?-amp 1? ?-material elastic|pimy? ?-su 50? ?-gmax 0.1?" }
array set opt {-base compliant -H 25.0 -n 50 -Vs 100.0 -rho 2.0 -nu 0.3 -Vr 160.0 -rhor 2.5 -damping 0.0 -f0 3.0 -t0 0.5 -tend 4.0 -dt 0.001 -amp 1.0 -material elastic -su 50.0 -gmax 0.1}
foreach {key value} [lrange $argv 1 end] {
  if {![info exists opt($key)]} { error "soil_column.tcl: unknown option '$key'" }
  set opt($key) $value
}
file mkdir $outdir
set H $opt(-H); set n $opt(-n); set Vs $opt(-Vs); set rho $opt(-rho); set nu $opt(-nu)
set dt $opt(-dt); set pi [expr {acos(-1.0)}]
set b 1.0                                  ;# column width (m); thickness 1 m, so A = b
set G [expr {$rho*$Vs*$Vs}]
set E [expr {2.0*$G*(1.0 + $nu)}]
set dz [expr {$H/double($n)}]

wipe
model basic -ndm 2 -ndf 2
# node (i, j): left i = 0, right i = 1, row j from the base; tags 2 j + i + 1
for {set j 0} {$j <= $n} {incr j} {
  node [expr {2*$j + 1}] 0.0 [expr {$j*$dz}]
  node [expr {2*$j + 2}] $b  [expr {$j*$dz}]
}
for {set j 1} {$j <= $n} {incr j} { equalDOF [expr {2*$j + 1}] [expr {2*$j + 2}] 1 2 }
if {$opt(-material) eq "elastic"} {
  nDMaterial ElasticIsotropic 1 $E $nu $rho
} elseif {$opt(-material) eq "pimy"} {
  set K [expr {$E/(3.0*(1.0 - 2.0*$nu))}]
  nDMaterial PressureIndependMultiYield 1 2 $rho $G $K $opt(-su) $opt(-gmax)
} else {
  error "soil_column.tcl: -material must be elastic or pimy, got '$opt(-material)'"
}
for {set j 0} {$j < $n} {incr j} {
  set n1 [expr {2*$j + 1}]
  element SSPquad [expr {$j + 1}] $n1 [expr {$n1 + 1}] [expr {$n1 + 3}] [expr {$n1 + 2}] 1 PlaneStrain 1.0
}
set surface [expr {2*$n + 1}]

# Ricker wavelet (1 - 2 (pi f0 (t - t0))^2) exp(-(pi f0 (t - t0))^2), sampled every dt up to tend
set nsteps [expr {int(round($opt(-tend)/$dt))}]
set values {}
for {set k 0} {$k <= $nsteps} {incr k} {
  set a [expr {$pi*$opt(-f0)*($k*$dt - $opt(-t0))}]
  lappend values [expr {$a*$a > 600.0 ? 0.0 : (1.0 - 2.0*$a*$a)*exp(-$a*$a)}]
}
timeSeries Path 1 -dt $dt -values $values -useLast

if {$opt(-base) eq "compliant"} {
  fix 1 0 1
  fix 2 0 1
  equalDOF 1 2 1
  set C [expr {$opt(-rhor)*$opt(-Vr)*$b}]
  node 2000 0.0 0.0
  fix 2000 1 1
  uniaxialMaterial Viscous 4000 $C 1.0
  element zeroLength 5000 2000 1 -mat 4000 -dir 1
  # Joyner & Chen (1975): F(t) = rho_r Vs_r A v_outcrop(t)
  pattern Plain 10 1 -fact [expr {$C*$opt(-amp)}] { load 1 1.0 0.0 }
  recorder Element -file $outdir/dashpot_force.out -time -precision 12 -ele 5000 force
  recorder Element -file $outdir/dashpot_deformation.out -time -precision 12 -ele 5000 deformation
} elseif {$opt(-base) eq "rigid"} {
  fix 1 1 1
  fix 2 1 1
  pattern UniformExcitation 10 1 -accel 1 -fact $opt(-amp)
} else {
  error "soil_column.tcl: -base must be compliant or rigid, got '$opt(-base)'"
}

if {$opt(-damping) > 0.0} {
  # Rayleigh damping xi at the first and third mode, f = Vs / 4H and 5 Vs / 4H (Chopra 2012, eq. 11.4.9)
  set w1 [expr {2.0*$pi*$Vs/(4.0*$H)}]
  set w3 [expr {5.0*$w1}]
  set xi $opt(-damping)
  rayleigh [expr {2.0*$xi*$w1*$w3/($w1 + $w3)}] [expr {2.0*$xi/($w1 + $w3)}] 0.0 0.0
}

print -JSON -file $outdir/model.json
recorder Node -file $outdir/surface_vel.out -time -precision 12 -node $surface -dof 1 vel
recorder Node -file $outdir/surface_accel.out -time -precision 12 -node $surface -dof 1 accel
recorder Node -file $outdir/base_vel.out -time -precision 12 -node 1 -dof 1 vel
recorder Element -file $outdir/base_stress.out -time -precision 12 -ele 1 stress
set input [open $outdir/input.out w]
for {set k 0} {$k <= $nsteps} {incr k} { puts $input "[expr {$k*$dt}] [lindex $values $k]" }
close $input

constraints Transformation
numberer RCM
system UmfPack
if {$opt(-material) eq "pimy"} {
  updateMaterialStage -material 1 -stage 1
  test NormDispIncr 1.0e-10 50
  algorithm Newton
} else {
  test NormDispIncr 1.0e-12 10
  algorithm Linear
}
integrator Newmark 0.5 0.25
analysis Transient
set ok [analyze $nsteps $dt]
if {$ok != 0} { error "soil_column.tcl: analyze returned $ok" }
puts stdout "soil_column: $nsteps steps of $dt s, base $opt(-base), surface velocity at the end [nodeVel $surface 1]"
