use rubber_band_box::measure::references::{Engine, StiffCase, run_engine};
use std::time::Instant;

#[test]
#[ignore]
fn orders() {
    let orders: Vec<usize> = std::env::var("ORDERS")
        .map(|v| v.split(',').map(|o| o.parse().unwrap()).collect())
        .unwrap_or(vec![20, 26, 28, 30, 32]);
    let ks: Vec<f64> = std::env::var("KS")
        .map(|v| v.split(',').map(|o| o.parse().unwrap()).collect())
        .unwrap_or(vec![20.0, 1e3, 1e5, 1e6, 1e7]);
    for k in ks {
        for rate in [100.0, 64.0] {
            let case = StiffCase::new(k, rate);
            let mass = case.scene.params.mass_properties().unwrap();
            let mut scenes = vec![];
            for (dx, dy) in [(0.0, 0.0), (0.5, 0.0), (0.0, 0.5), (-0.7, 0.3), (0.2, -0.9)] {
                let mut scene = case.scene.clone();
                scene.pulls[0].2.x += dx;
                scene.pulls[0].2.y += dy;
                let reference = run_engine(
                    &scene,
                    rate,
                    case.ticks,
                    Engine::Taylor(
                        std::env::var("REF")
                            .map(|t| t.parse().unwrap())
                            .unwrap_or(24),
                        1e-15,
                    ),
                )
                .unwrap()
                .0;
                let check = run_engine(&scene, rate, case.ticks, Engine::Dop853(1e-13))
                    .unwrap()
                    .0;
                scenes.push((scene, reference, reference.pose_error(&check, &mass), check));
            }
            for &order in &orders {
                let mut errors = vec![];
                let mut dop_errors: Vec<f64> = vec![];
                let mut work = 0.0;
                let mut best = f64::INFINITY;
                for (scene, reference, _, dop) in &scenes {
                    let (state, orders) = run_engine(
                        scene,
                        rate,
                        case.ticks,
                        Engine::Taylor(
                            order,
                            std::env::var("TOL")
                                .map(|t| t.parse().unwrap())
                                .unwrap_or(1e-10),
                        ),
                    )
                    .unwrap();
                    errors.push(state.pose_error(reference, &mass));
                    dop_errors.push(state.pose_error(dop, &mass));
                    work += orders;
                }
                for _ in 0..30 {
                    let t = Instant::now();
                    for (scene, _, _, _) in &scenes {
                        std::hint::black_box(run_engine(
                            scene,
                            rate,
                            case.ticks,
                            Engine::Taylor(
                                order,
                                std::env::var("TOL")
                                    .map(|t| t.parse().unwrap())
                                    .unwrap_or(1e-10),
                            ),
                        ));
                    }
                    best = best.min(t.elapsed().as_secs_f64());
                }
                let max = errors.iter().cloned().fold(0.0, f64::max);
                let dmax = dop_errors.iter().cloned().fold(0.0, f64::max);
                println!(
                    "k {k:e} {rate} Hz order {order}: orders/tick {:.0} steps/tick {:.1} time {:.2} us/tick max err {max:.2e} (dop {dmax:.2e}) errs {:?}",
                    work / 5.0,
                    work / 5.0 / order as f64,
                    best / 5.0 * 1e6 / case.ticks as f64,
                    errors
                        .iter()
                        .map(|e| format!("{e:.1e}"))
                        .collect::<Vec<_>>()
                );
                println!(
                    "   dop errs {:?}",
                    dop_errors
                        .iter()
                        .map(|e| format!("{e:.1e}"))
                        .collect::<Vec<_>>()
                );
            }
            println!(
                "k {k:e} {rate} agreements {:?}",
                scenes
                    .iter()
                    .map(|s| format!("{:.1e}", s.2))
                    .collect::<Vec<_>>()
            );
        }
    }
}
