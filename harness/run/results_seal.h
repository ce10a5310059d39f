// The seal on a run's results.json: an HMAC-SHA256 of its bytes, keyed by a secret of this
// user (a file of the user's cache folder, mode 0600, made on first use), in RESULTS.seal
// beside it. `run --verdict-from` reuses an earlier run's verdicts only from a file whose
// seal matches, so a results.json edited by hand or by another program (a status turned from
// fail to pass, a fingerprint made to match) renders its cases instead of passing them.
// It protects against edits, not against a user who reads their own key: the verdicts are
// the user's own either way.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace taa::run {

// RESULTS + ".seal".
std::filesystem::path sealPathOf(const std::filesystem::path& results);

// Writes `text` to `results` (writeFileAtomically) and its seal beside it. The old seal goes
// first, so a results file is never left beside a seal of other bytes. Without a key (no cache
// folder, or a key file that is not the user's alone) the file is written unsealed and the
// reason returned, for a note; "" when sealed.
std::string writeSealedResults(const std::filesystem::path& results, const std::string& text);

// Writes `text` to `results` with no seal (its old seal removed first): results made from
// files whose seals did not hold (a merge of such a shard) are not to be trusted either.
void writeUnsealedResults(const std::filesystem::path& results, const std::string& text);

// "" when `text` (the bytes read from `results`) carries this user's seal, else why not, in
// words for a NOTE ("results.json.seal is missing", "does not match the file's bytes").
std::string sealProblem(const std::filesystem::path& results, const std::string& text);

// HMAC-SHA256 (RFC 2104) of `message` under `key`, as 64 lowercase hex digits.
std::string hmacSha256Hex(std::string_view key, std::string_view message);

}  // namespace taa::run
