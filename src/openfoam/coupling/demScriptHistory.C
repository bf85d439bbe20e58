#include "demScriptHistory.H"
#include <vector>

namespace Foam
{

namespace
{
// One word of a command: where it starts in the text and its length; quoted words are skipped
struct word_at { size_t pos, len; bool quoted; };

// The words of a LIGGGHTS command text[begin, end) (continuations joined, comments dropped)
std::vector<word_at> commandWords(const std::string& text, size_t begin, size_t end)
{
    std::vector<word_at> words;
    size_t i = begin;
    while (i < end)
    {
        const char c = text[i];
        if (c == '#') { while (i < end && text[i] != '\n') ++i; continue; }   // a comment to the line's end
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '&') { ++i; continue; }
        if (c == '"' || c == '\'')
        {
            const size_t start = i++;
            while (i < end && text[i] != c) ++i;
            words.push_back({start, ++i - start, true});
            continue;
        }
        const size_t start = i;
        while (i < end && std::string(" \t\n\r&#\"'").find(text[i]) == std::string::npos) ++i;
        words.push_back({start, i - start, false});
    }
    return words;
}

// The end of the command that starts at `begin`: the newline not preceded by '&' (ignoring spaces)
size_t commandEnd(const std::string& text, size_t begin)
{
    size_t i = begin;
    while (i < text.size())
    {
        if (text[i] == '\n')
        {
            size_t j = i;
            while (j > begin && (text[j - 1] == ' ' || text[j - 1] == '\t' || text[j - 1] == '\r')) --j;
            if (j == begin || text[j - 1] != '&') return i;
        }
        ++i;
    }
    return text.size();
}
}

std::string appendingHistory(const std::string& script, label& nChanged)
{
    nChanged = 0;
    std::string out = script;
    size_t begin = 0;
    while (begin < out.size())
    {
        const size_t end = commandEnd(out, begin);
        const std::vector<word_at> w = commandWords(out, begin, end);
        auto is = [&](size_t k, const char* s) { return k < w.size() && !w[k].quoted && out.compare(w[k].pos, w[k].len, s) == 0; };
        if (is(0, "fix") && is(3, "print"))
        {
            // from the last word back, so that the earlier positions stay valid
            for (size_t k = w.size(); k-- > 4;)
            {
                if (is(k, "file") && k + 1 < w.size())
                {
                    out.replace(w[k].pos, w[k].len, "append");
                    ++nChanged;
                }
            }
        }
        begin = commandEnd(out, begin) + 1;
    }
    return out;
}

} // End namespace Foam
