set term png small color
set size .7,.5
set logscale y
set output "spring.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:2 with lines 1
set nologscale y
set output "istress.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:6 with lines 4
set output "deltat.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:3 with lines 2
set output "openclose.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:4 with lines 3
set output "openclosecut.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:7 with lines 3
set output "ke.png"
plot "/work/main/ntdda_out/output/bench_data.m" using 1:5 with lines 4
set nokey
set xrange [1:1601]
set yrange [1601:1]
set size square
set output "spy1.png"
plot "/work/main/ntdda_out/output/bench.spy1" with points
set output "spy2.png"
plot "/work/main/ntdda_out/output/bench.spy2" with points
