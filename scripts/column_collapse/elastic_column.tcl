# The main job (README): the reference scene's soil column, elastic, under gravity.
# Sordo, Rathje & Kumar (hybrid FEM-MPM granular column collapse): a 50 m wide x 40 m high column meshed with
# 1 m x 1 m SSPquad elements (plane strain), E = 172 MPa, nu = 0.23, rho = 1925 kg/m3, g = 9.81 m/s2.
# Supports: base fixed (x and y), left face on vertical rollers (symmetry plane), right face free.
# Units: kN, m, s (stress in kPa, density in Mg/m3 = t/m3).
# Usage: fem_tcl elastic_column.tcl ?nx ny?   (default 50 40 elements; the element size is 50/nx x 40/ny m)
# Prints the vertical stress of the base centre element against the analytical -rho g (H - y_c) at its
# centroid depth, the lateral stress ratio against K0 = nu / (1 - nu), and the top settlement at the centre
# against the 1D (laterally confined) estimate rho g H^2 / (2 M), M = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
# Near the free right face the column is not laterally confined, so the settlement differs from the 1D value.
wipe
model basic -ndm 2 -ndf 2

set W 50.0
set H 40.0
set nx [expr {$argc >= 1 ? [lindex $argv 0] : 50}]
set ny [expr {$argc >= 2 ? [lindex $argv 1] : 40}]
set dx [expr {$W / $nx}]
set dy [expr {$H / $ny}]

set E 172.0e3     ;# kPa
set nu 0.23
set rho 1.925     ;# Mg/m3
set g 9.81        ;# m/s2

for {set j 0} {$j <= $ny} {incr j} {
    for {set i 0} {$i <= $nx} {incr i} {
        node [expr {$j*($nx+1) + $i + 1}] [expr {$i*$dx}] [expr {$j*$dy}]
    }
}
fixY 0.0 1 1
fixX 0.0 1 0

nDMaterial ElasticIsotropic 1 $E $nu $rho
set e 0
for {set j 0} {$j < $ny} {incr j} {
    for {set i 0} {$i < $nx} {incr i} {
        incr e
        set n1 [expr {$j*($nx+1) + $i + 1}]
        element SSPquad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1 PlaneStrain 1.0 0.0 [expr {-$rho*$g}]
    }
}

constraints Transformation
numberer RCM
system SparseSYM
test NormDispIncr 1.0e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
set ok [analyze 1]
if {$ok != 0} { error "elastic column: gravity analysis failed ($ok)" }

# base centre element: bottom row, the element whose left edge is at x = W/2
set iC [expr {int($nx/2)}]
set eC [expr {$iC + 1}]
set yc [expr {0.5*$dy}]
set s [eleResponse $eC stress]
set sxx [lindex $s 0]
set syy [lindex $s 1]
set syyRef [expr {-$rho*$g*($H - $yc)}]
set K0 [expr {$nu/(1.0 - $nu)}]
set M [expr {$E*(1.0 - $nu)/((1.0 + $nu)*(1.0 - 2.0*$nu))}]
set topCentre [expr {$ny*($nx+1) + $iC + 1}]
set settle [expr {-[nodeDisp $topCentre 2]}]
set settleRef [expr {$rho*$g*$H*$H/(2.0*$M)}]

puts stdout "elastic column ${W} m x ${H} m, ${nx} x ${ny} SSPquads, units kN m s (kPa)"
puts stdout [format "base centre element %d (centroid depth %.2f m): syy = %.3f kPa, analytical -rho g (H - y) = %.3f kPa, error %.3f %%" \
    $eC [expr {$H - $yc}] $syy $syyRef [expr {100.0*($syy - $syyRef)/abs($syyRef)}]]
puts stdout [format "lateral ratio sxx/syy = %.4f, K0 = nu/(1-nu) = %.4f" [expr {$sxx/$syy}] $K0]
puts stdout [format "top settlement at x = %.1f m: %.5f m, 1D confined estimate rho g H^2/(2M) = %.5f m" \
    [expr {$iC*$dx}] $settle $settleRef]
wipe
