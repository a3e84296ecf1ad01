//! The recommended heading: the bank's, averaged with Table-III HDR's where the two agree.
//! Two estimators whose errors differ in kind (the bank's road model is wrong where the road
//! is not as modelled; HDR's fixed-rate heuristic cannot acquire a bias it did not start
//! near, and follows a slow change the bank lags) are averaged, with a guard: over each block
//! the heading moves by the mean of the two headings' moves when the bias they imply
//! differ by less than `hdr_blend_sigmas` of the bank's bias uncertainty, and by the bank's
//! alone otherwise (HDR diverging, or the bank correcting its heading at a stop). HDR starts
//! at the end of the lead-in from the bank's bias then (its static bias, eps0), so the
//! stream and the batch path blend alike, block for block. Beyond the paper, like the bank.

use super::filter::PipelineOutput;
use crate::error::Result;
use crate::hdr::{Hdr, HdrParams};

/// The blend beside a bank: HDR on the blocks from the end of the lead-in, the two headings
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
        let hdr = match self.hdr.as_mut() {
            Some(h) => h,
            None => self.hdr.insert(Hdr::new(HdrParams::table_iii(), bank.bias_dps)?),
        };
        let hdr_heading_deg = hdr.update(time_s, rate_dps)?.heading_deg;
        let mut out = bank;
        if let Some((t, bank_deg, hdr_deg)) = self.last {
            // HDR's bias less the bank's over the block, from the headings' moves.
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

    fn bank(heading_deg: f64) -> PipelineOutput {
        PipelineOutput {
            heading_deg,
            bias_dps: 0.0,
            bias_sigma_dps: 0.1,
            heading_sigma_deg: 0.0,
            stop: false,
            straight: false,
            reopened: false,
        }
    }

    #[test]
    fn agreeing_headings_are_averaged_and_a_diverging_one_is_left_out() {
        let mut b = Blend::default();
        // In the lead-in, or with the blend off, the bank's output as it is.
        assert_eq!(b.update(2.0, false, 0.0, 0.0, bank(0.3)).unwrap(), bank(0.3));
        assert_eq!(b.update(0.0, true, 0.0, 0.0, bank(0.3)).unwrap(), bank(0.3));
        assert!(b.hdr.is_none());
        // HDR from eps0 = the bank's bias (0) on a rate of 0: its heading h1 after 1 s moves
        // only by its controller (at most Table III's i_c, 0.0422 deg/s, per step).
        assert_eq!(b.update(2.0, true, 0.0, 0.0, bank(0.0)).unwrap(), bank(0.0));
        let h1 = b.hdr.clone().unwrap().update(1.0, 0.0).unwrap().heading_deg;
        assert!(h1.abs() <= 0.0422 + 1e-12);
        // The bank moved 0.1 deg in 1 s: 0.1 - h1 apart, within 2 x 0.1 deg/s, so the blend
        // takes the mean of the two moves, and the bias the bank's less half the difference.
        let o = b.update(2.0, true, 1.0, 0.0, bank(0.1)).unwrap();
        assert!((o.heading_deg - (0.1 + h1) / 2.0).abs() < 1e-12, "{} against {}", o.heading_deg, (0.1 + h1) / 2.0);
        assert!((o.bias_dps - (0.1 - h1) / 2.0).abs() < 1e-12, "{}", o.bias_dps);
        // Then the bank jumps 5 deg in a block (a stop's correction): 5 deg/s apart, beyond
        // 2 sigma, so the blend moves with the bank alone and keeps its offset.
        let offset = o.heading_deg - 0.1;
        let o = b.update(2.0, true, 2.0, 0.0, bank(5.1)).unwrap();
        assert!((o.heading_deg - (5.1 + offset)).abs() < 1e-12 && o.bias_dps == 0.0);
    }
}
