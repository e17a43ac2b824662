#include "pseudonyms.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"

#include <nlohmann/json.hpp>
#include <sodium.h>

#include <cstdio>
#include <vector>

namespace raylab {

namespace fs = std::filesystem;

namespace {

std::string hex(const unsigned char* bytes, std::size_t n) {
    std::string out;
    char two[3];
    for (std::size_t i = 0; i < n; ++i) {
        std::snprintf(two, sizeof two, "%02x", bytes[i]);
        out += two;
    }
    return out;
}

}  // namespace

PseudonymKey::PseudonymKey(const fs::path& keyFile) : file_(keyFile) {
    if (sodium_init() < 0) throw Error("libsodium cannot start");
    const std::string shown = "--anonymise " + keyFile.string();
    std::error_code ec;
    if (!fs::exists(keyFile, ec)) {
        key_.resize(crypto_generichash_KEYBYTES);
        randombytes_buf(key_.data(), key_.size());
        return;
    }
    try {
        const nlohmann::json doc = nlohmann::json::parse(readTextFile(keyFile));
        const std::string h = doc.at("key").get<std::string>();
        if (h.size() != 2 * crypto_generichash_KEYBYTES) throw Error("");
        key_.resize(crypto_generichash_KEYBYTES);
        std::size_t n = 0;
        if (sodium_hex2bin(reinterpret_cast<unsigned char*>(key_.data()), key_.size(), h.c_str(),
                           h.size(), nullptr, &n, nullptr) != 0 ||
            n != key_.size())
            throw Error("");
        const nlohmann::json known = doc.value("pseudonyms", nlohmann::json::object());
        for (const auto& [pseudonym, name] : known.items())
            names_[pseudonym] = name.get<std::string>();
    } catch (const std::exception&) {
        throw Error(shown + ": not a key file raylab wrote (a new path makes a new key)");
    }
}

std::string PseudonymKey::pseudonym(const std::string& name) {
    unsigned char hash[16];
    crypto_generichash(hash, sizeof hash, reinterpret_cast<const unsigned char*>(name.data()),
                       name.size(), reinterpret_cast<const unsigned char*>(key_.data()),
                       key_.size());
    const std::string p = "student-" + hex(hash, 4);
    names_[p] = name;
    return p;
}

std::string PseudonymKey::nameOf(const std::string& pseudonym) const {
    auto it = names_.find(pseudonym);
    return it == names_.end() ? "" : it->second;
}

void PseudonymKey::save() const {
    nlohmann::json doc = {
        {"comment", "raylab grade --anonymise: the key of the pseudonyms and whose each is. Keep "
                    "it from the TAs; the same file gives the same pseudonyms next time."},
        {"key", hex(reinterpret_cast<const unsigned char*>(key_.data()), key_.size())},
        {"pseudonyms", names_}};
    writeTextFileAtomic(file_, doc.dump(1) + "\n");
    std::error_code ec;
    fs::permissions(file_, fs::perms::owner_read | fs::perms::owner_write, ec);
}

namespace {

// TEXT with each of FORMS replaced by REPLACEMENT, on after each replacement
// (the replacement may hold a form: "stud" in "student-...").
std::string replaceAll(std::string text, const std::vector<std::string>& forms,
                       const std::string& replacement) {
    for (const std::string& form : forms) {
        if (form.empty()) continue;
        for (std::size_t at = text.find(form); at != std::string::npos;
             at = text.find(form, at + replacement.size()))
            text.replace(at, form.size(), replacement);
    }
    return text;
}

// The ways a message may write FOLDER: as given, absolute, canonical, as
// shown from the working folder.
std::vector<std::string> folderForms(const fs::path& folder) {
    std::error_code ec;
    return {fs::weakly_canonical(folder, ec).string(), fs::absolute(folder, ec).string(),
            folder.string(), displayPath(folder)};
}

}  // namespace

std::string withoutName(std::string text, const std::string& name, const std::string& pseudonym,
                        const fs::path& submissions) {
    std::vector<std::string> forms = folderForms(submissions / name);
    // The bare name too, where it is long enough not to hit ordinary words.
    if (name.size() >= 4) forms.push_back(name);
    return replaceAll(std::move(text), forms, pseudonym);
}

std::string withoutMachinePath(std::string text, const std::string& name,
                               const fs::path& submissions) {
    return replaceAll(std::move(text), folderForms(submissions / name), name);
}

void scrubNames(const fs::path& log, const std::string& name, const std::string& pseudonym,
                const fs::path& submissions) {
    std::error_code ec;
    if (!fs::is_regular_file(log, ec)) return;
    const std::string text = readTextFile(log);
    const std::string clean = name == pseudonym ? withoutMachinePath(text, name, submissions)
                                                : withoutName(text, name, pseudonym, submissions);
    if (clean != text) writeTextFileAtomic(log, clean);
}

}  // namespace raylab
