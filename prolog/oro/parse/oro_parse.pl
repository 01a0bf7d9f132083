:- module(oro_parse,
          [ oro_tokenize/3,             % +Text, +Delimiter, -Tokens
            oro_clean_value/2,          % +Text, -String
            oro_parse_collection/3,     % +Kind, +Text, -Elements
            oro_parse_map/2,            % +Text, -Pairs
            oro_parse_statement/2,      % +Text, -Triple
            oro_parse_statements/2,     % +Texts, -Triples
            oro_is_partial/1,           % +Triple
            oro_statements/3,           % +Statements, -Triples, -Bindings
            oro_complete_statements/2,  % +Statements, -Triples
            oro_parse_budget/1          % :Goal
          ]).
:- reexport(library(oro/parse/oro_parse_lexer),
            [ oro_tokenize/3,
              oro_clean_value/2
            ]).
:- reexport(library(oro/parse/oro_parse_statement),
            [ oro_parse_collection/3,
              oro_parse_map/2,
              oro_parse_statement/2,
              oro_parse_statements/2,
              oro_is_partial/1,
              oro_statements/3,
              oro_complete_statements/2
            ]).
:- reexport(library(oro/parse/oro_parse_budget),
            [ oro_parse_budget/1
            ]).

/** <module> Parsing of ORO request parameters and statements

This module decodes the text of request parameters as oro-server 0.8.2
does (ORO-SPEC §2) and turns statement texts into rdf_db triples (§4.2,
§4.3).  Everything here is pure: no predicate touches the store, so a
batch that fails half-way has nothing to undo.

  - oro_tokenize/3 is ORO's tokenizer: it splits on a delimiter only
    outside `[ ]`, `{ }` and quotes, keeping empty tokens.
  - oro_clean_value/2 is ORO's `cleanValue`: trim, drop one outer pair
    of quotes, Java-unescape.
  - oro_parse_collection/3 and oro_parse_map/2 decode `[a, "b"]` and
    `{k:v}` parameters into lists of strings.
  - oro_parse_statement/2 turns `subject predicate object` into
    `rdf(S, P, O)`, where each position is an IRI, an rdf_db literal term
    (objects only) or `var(Name)` for a `?name` token.

Object tokens follow ORO's literal rules: `true`/`false` are booleans,
quoted text is an `xsd:string`, `[+-]?[0-9]+` is an `xsd:int`, decimal and
exponent forms are `xsd:double`, `lex^^type` is a typed literal whose
lexical form is checked against the XSD datatype, `"text"@lang` is a
language-tagged literal, anything else is a resource.  Lexical forms are
kept as written, as atoms.

Errors are ISO-shaped, `error(Formal, _)`:

  | Formal                                        | raised for                       |
  |-----------------------------------------------|----------------------------------|
  | `type_error(oro_collection, Text)`            | a set/list not framed by `[ ]`   |
  | `type_error(oro_map, Text)`                   | a map not framed by `{ }` or an entry without `:` |
  | `syntax_error(oro_unicode_escape(Text))`      | a malformed `\uXXXX` escape      |
  | `syntax_error(oro_statement_tokens(N, Stmt))` | a statement without 3 tokens     |
  | `syntax_error(oro_statement_empty_token(Stmt))` | 3 tokens, one of them empty (two spaces) |
  | `syntax_error(oro_statement_variable(Stmt))`  | a bare `?` token                 |
  | `type_error(oro_statement, Stmt)`             | a token with an unterminated quote (`a b "c`), or an object opening with a quote that is no literal (`"a"b`) |
  | `syntax_error(oro_invalid_datatype(Type))`    | an unknown `xsd:` datatype, or an empty one |
  | `syntax_error(oro_lexical_form(Lex, Type))`   | a lexical form its datatype rejects |
  | `syntax_error(oro_statement_literal(Stmt))`   | a literal object of a predicate that needs a resource (oro_complete_statements/2) |
  | `syntax_error(oro_statement_name(Token))`     | a name with a bracket or brace (`[[a]]`) outside `<...>` |
  | `resource_error(oro_nesting(Max))`            | brackets or braces nested deeper than the `max_nesting` setting |
  | `resource_error(oro_parse_limit(Limit))`      | a request whose parsing ran past the `inference_limit` setting |

Texts inside error terms are strings.

## Speed

Parsing is on the path of every request, so the common case is kept to
a few C-level scans per text.  A text with none of the characters the
tokenizer and `cleanValue` track (quotes, brackets, braces, backslash,
control characters; see plain_text/1) is split with split_string/4
directly: a set of such statements, an unquoted statement and the
names in it take this *fast path*.  So does a set whose elements are
all quoted with one quote, as liboro and pyoro send them
(quoted_elements/2), and a set of unquoted statements with a quoted
label in it (one_quote_elements/2).  Other texts are tokenized from one
tracked character to the next, found by split_string/4, the plain text
between them split at once (scan_tokenize/3); the general, code-by-code
path is left for texts with NUL.  All give the same results
(test/test_parse.pl runs them over corpora of tricky and random
inputs); a fast path only skips work that provably does nothing on the
texts it takes.

## Bounded cost

Every text costs time and memory in proportion to its length, with a
small constant (bench/bench_parse.pl measures the worst constructs and
README's limits table gives the figures):

  - Texts are scanned in chunks of chunk_chars/1 characters
    (one_part/2, scan_tokenize/3), so a text full of tracked characters
    does not make one string per character before anything is
    decided.
  - The depth of `[ ]` and of `{ }` the tokenizer tracks is limited
    by the setting `max_nesting` (default 32; ORO's parameters nest 2
    deep): past it, `resource_error(oro_nesting(Max))` is raised as soon
    as the scan reaches it, within the first chunk of a text of nested
    brackets however long.
  - A name never holds a bracket or a brace outside `<...>`
    (`syntax_error(oro_statement_name(Token))`): `[[[x]]]` is not
    stored as a name.
  - The parsing of one request has a CPU budget, counted in Prolog
    inferences so that it does not depend on the machine's load: the
    setting `inference_limit` (default 50,000,000, which the costliest
    constructs spend in 14 s of CPU on the project's VM and plain
    statements in 5 s; 0 for none).  oro_parse_budget/1 opens the
    request's budget, and every public predicate of this module given
    a text of 64 Ki characters or more spends from it (texts below that
    cost a few milliseconds at most).  Past it,
    `resource_error(oro_parse_limit(Limit))` is raised.

## Parts

The parser is four modules under `library(oro/parse/...)`; this one
puts them together and exports what the rest of oro uses:

  | module                | owns                                                    |
  |-----------------------|---------------------------------------------------------|
  | oro_parse_statement   | sets, lists, maps, statements, the API's statements     |
  | oro_parse_literal     | ORO's literal rules, the XSD lexical forms              |
  | oro_parse_lexer       | the tokenizer, `cleanValue` and the character scans     |
  | oro_parse_budget      | the parse budget and the `max_nesting` and `inference_limit` settings |

Each imports only modules listed below it, so there is no cycle.  The
settings keep their names in this module
(`oro_parse:max_nesting`, `oro_parse:inference_limit`).
*/
