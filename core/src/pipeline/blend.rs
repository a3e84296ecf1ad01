//! The recommended heading: the bank's, averaged with Table-III HDR's where the two agree.
//! Two estimators whose errors differ in kind (the bank's road model is wrong where the road
//! is not as modelled; HDR's fixed-rate heuristic cannot acquire a bias it did not start
//! near, and follows a slow change the bank lags) are averaged, with a guard: over each block
//! the heading moves by the mean of the two headings' moves when the biases they imply
//! differ by less than `hdr_blend_sigmas` of the bank's bias uncertainty, and by the bank's
//! alone otherwise (HDR diverging, or the bank correcting its heading at a stop). HDR starts
//! after the lead-in, at the first block where the bank knows its bias to better than one
//! of HDR's own correction steps (Table III's i_c, 0.0422 deg/s: HDR's static bias eps0 is
//! a standstill's, known that well), from the bank's bias then; before, the bank's alone.
//! The stream and the batch path blend alike, block for block. Beyond the paper, like the bank.

use super::filter::PipelineOutput;
use crate::error::Result;
use crate::hdr::{Hdr, HdrParams};

/// The blend beside a bank: HDR on the blocks once the bank knows its bias, the two headings
/// at the last block, the offset the blend has added to the bank's heading.
#[derive(Debug, Clone, Default)]
pub struct Blend {
    hdr: Option<Hdr>,
    last: Option<(f64, f64, f64)>,
    offset_deg: f64,
}

impl Blend {
    /// One block (end time, mean raw rate) and the bank's output on it: the output with the
    /// blended heading and the bias it integrated. `sigmas` is `hdr_blend_sigmas` (0: the
    /// bank's output as it is); `after_lead_in`: the block is past the lead-in.
    pub fn update(&mut self, sigmas: f64, after_lead_in: bool, time_s: f64, rate_dps: f64, bank: PipelineOutput) -> Result<PipelineOutput> {
        if !(sigmas > 0.0 && after_lead_in) {
            return Ok(bank);
        }
        let table_iii = HdrParams::table_iii();
        if self.hdr.is_none() && !(bank.bias_sigma_dps < table_iii.i_c_dps) {
            return Ok(bank);
        }
        let hdr = match self.hdr.as_mut() {
            Some(h) => h,
            None => self.hdr.insert(Hdr::new(table_iii, bank.bias_dps)?),
        };
        let hdr_heading_deg = hdr.update(time_s, rate_dps)?.heading_deg;
        let mut out = bank;
        if let Some((t, bank_deg, hdr_deg)) = self.last {
            // How far the two headings moved apart over the block: (the bank's bias less
            // HDR's, as each integrated it) x dt.
            let apart_deg = (hdr_heading_deg - hdr_deg) - (bank.heading_deg - bank_deg);
            let dt = time_s - t;
            if dt > 0.0 && (apart_deg / dt).abs() < sigmas * bank.bias_sigma_dps {
                self.offset_deg += 0.5 * apart_deg;
                out.bias_dps -= 0.5 * apart_deg / dt;
            }
        }
        self.last = Some((time_s, bank.heading_deg, hdr_heading_deg));
        out.heading_deg += self.offset_deg;
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bank(heading_deg: f64, bias_sigma_dps: f64) -> PipelineOutput {
        PipelineOutput { heading_deg, bias_dps: 0.0, bias_sigma_dps, heading_sigma_deg: 0.0, stop: false, straight: false, reopened: false }
    }

    #[test]
    fn agreeing_headings_are_averaged_and_a_diverging_one_is_left_out() {
        let mut b = Blend::default();
        // In the lead-in, with the blend off, or while the bank's bias is less sure than one
        // of HDR's steps (0.0422 deg/s), the bank's output as it is, and HDR not started.
        assert_eq!(b.update(2.0, false, 0.0, 0.0, bank(0.3, 0.03)).unwrap(), bank(0.3, 0.03));
        assert_eq!(b.update(0.0, true, 0.0, 0.0, bank(0.3, 0.03)).unwrap(), bank(0.3, 0.03));
        assert_eq!(b.update(2.0, true, 0.0, 0.0, bank(0.3, 0.05)).unwrap(), bank(0.3, 0.05));
        assert!(b.hdr.is_none());
        // HDR from eps0 = the bank's bias (0) on a rate of 0; h1, its heading after 1 s,
        // moves only by its controller (at most i_c per step).
        assert_eq!(b.update(2.0, true, 1.0, 0.0, bank(0.0, 0.03)).unwrap(), bank(0.0, 0.03));
        let h1 = b.hdr.clone().unwrap().update(2.0, 0.0).unwrap().heading_deg;
        assert!(h1.abs() <= 0.0422 + 1e-12);
        // The bank moved h1 + 0.05 deg in 1 s: 0.05 deg/s apart, within 2 x 0.03, so the
        // blend takes the mean of the two moves, and the bias the bank's less half the gap.
        let o = b.update(2.0, true, 2.0, 0.0, bank(h1 + 0.05, 0.03)).unwrap();
        assert!((o.heading_deg - (h1 + 0.025)).abs() < 1e-12, "{} against {}", o.heading_deg, h1 + 0.025);
        assert!((o.bias_dps - 0.025).abs() < 1e-12, "{}", o.bias_dps);
        // 0.07 deg/s apart next: beyond 2 sigma, the bank's move alone, the offset kept.
        let o = b.update(2.0, true, 3.0, 0.0, bank(h1 + 0.05 + 0.07, 0.03)).unwrap();
        let h2 = b.last.unwrap().2;
        assert!((h2 - h1).abs() < 1e-12, "HDR still on the rate of 0: {h2}");
        assert!((o.heading_deg - (h1 + 0.05 + 0.07 - 0.025)).abs() < 1e-12 && o.bias_dps == 0.0);
    }
}
