:- module(oro_parse_statement,
          [ oro_parse_collection/3,     % +Kind, +Text, -Elements
            oro_parse_map/2,            % +Text, -Pairs
            oro_parse_statement/2,      % +Text, -Triple
            oro_parse_statements/2,     % +Texts, -Triples
            oro_is_partial/1,           % +Triple
            oro_statements/3,           % +Statements, -Triples, -Bindings
            oro_complete_statements/2   % +Statements, -Triples
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/parse/oro_parse_budget)).
:- use_module(library(oro/parse/oro_parse_lexer)).
:- use_module(library(oro/parse/oro_parse_literal)).

/** <module> The syntax of ORO's collections, maps and statements

This module owns what ORO builds from the tokens of oro_parse_lexer
(ORO-SPEC §2, §4.2, §4.3):

  - oro_parse_collection/3 and oro_parse_map/2 decode `[a, "b"]` and
    `{k:v}` parameters into lists of strings.
  - oro_parse_statement/2 turns `subject predicate object` into
    `rdf(S, P, O)`, where each position is an IRI, an rdf_db literal term
    (objects only, see oro_parse_literal) or `var(Name)` for a `?name`
    token.
  - oro_statements/3 and oro_complete_statements/2 normalise the
    statements the API takes, texts or rdf/3 terms, for queries and for
    changes.

The fast paths of collections and statements (see the module doc of
oro_parse, "Speed") are here, beside the general paths they give the
same results as.  Every public predicate spends from the parse budget
(oro_parse_budget).
*/

                 /*******************************
                 *       SETS, LISTS, MAPS      *
                 *******************************/

%!  oro_parse_collection(+Kind, +Text, -Elements:list(string)) is det.
%
%   Decode a `Set<String>` (Kind `set`) or `List<String>` (Kind `list`)
%   parameter.  The empty text and `null` (any case) give `[]`.
%   Otherwise Text must start with `[` and end with `]` (it is not
%   trimmed); the inside is split on `,` by oro_tokenize/3 and each
%   element goes through oro_clean_value/2.  `[]` gives `[]`, `[ ]`
%   gives `[""]`.  A set drops duplicates, keeping the first occurrence
%   of each element; a list keeps order and duplicates.
%
%   @error domain_error(oneof([set, list]), Kind) for another Kind.
%   @error type_error(oro_collection, Text) if Text is not framed by
%          `[ ]`.
%   @error syntax_error(oro_unicode_escape(Element)) from
%          oro_clean_value/2.

oro_parse_collection(Kind, Text, Elements) :-
    must_be(atom, Kind),
    (   collection_kind(Kind)
    ->  true
    ;   domain_error(oneof([set, list]), Kind)
    ),
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, collection(Kind, Text, Elements)).

collection(Kind, Text, Elements) :-
    collection_elements(Text, Elements0),
    (   Kind == set
    ->  set_elements(Elements0, Elements)
    ;   Elements = Elements0
    ).

%   set_elements(+List, -Set): List less its duplicates, the first
%   occurrence of each kept.  A batch rarely has any: one sort tells.

set_elements(List, Set) :-
    sort(List, Sorted),
    (   same_length(List, Sorted)
    ->  Set = List
    ;   list_to_set(List, Set)
    ).

collection_kind(set).
collection_kind(list).

collection_elements(Text, Elements) :-
    (   null_text(Text)
    ->  Elements = []
    ;   framed(Text, 0'[, 0'], Inner)
    ->  (   Inner == ""
        ->  Elements = []
        ;   quoted_elements(Inner, Elements0)
        ->  Elements = Elements0
        ;   plain_text(Inner)               % split, trim: one C call
        ->  split_string(Inner, ",", " ", Elements)
        ;   one_quote_elements(Inner, Elements0)
        ->  Elements = Elements0
        ;   general_elements(Inner, Elements)
        )
    ;   throw(error(type_error(oro_collection, Text), _))
    ).

%   quoted_elements(+Inner, -Elements): the fast path for the inside of
%   a collection whose elements are all quoted with the same quote, as
%   the clients send them: liboro `"a b c","d \"e\" f"`, pyoro `'a b
%   c', 'd e "f"'`.  It applies when the elements hold no bracket or
%   brace, no backslash but one escaping the quote, and the other quote
%   an even number of times, and are separated by one comma with spaces
%   around it at most.  The general path then splits exactly at those
%   commas (the quote's flag is on inside each element, the other
%   quote's flag is off again at its end), trims what is around the
%   quotes and takes them off, and its unescaping turns each escaped
%   quote into the quote: each element is what lies between its quotes,
%   escapes undone (a control character inside is kept either way).
%   Fails on anything else.

quoted_elements(Inner, Elements) :-
    opening_quote(Inner, Code),
    quote_pair(Code, Quote, Other),
    one_part(Inner, "[]{}"),
    (   sub_atom_icasechk(Inner, _, "\\")
    ->  split_string(Inner, "\\", "", [_|Escaped]),
        maplist(escaped_quote(Quote), Escaped),
        Escapes = true
    ;   Escapes = false
    ),
    (   sub_atom_icasechk(Inner, _, Other)
    ->  Others = true
    ;   Others = false
    ),
    split_string(Inner, Quote, "", [Before|Parts]),
    split_string(Before, "", " ", [""]),
    quoted_parts(Parts, q(Quote, Escapes, Other, Others), Elements).

%   one_quote_elements(+Inner, -Elements): the fast path for the inside
%   of a collection whose only special characters are quotes of one
%   kind, none of which opens an element, with no comma between a quote
%   and the next: a set of statements sent unquoted, one of them with a
%   label, `a rdf:type Cup, a rdfs:label "cup 1", b isOn a`.  (No
%   bracket, brace, backslash or control character: see
%   quote_specials/1.)  The tokenizer's only state is then the quote's
%   flag, which is off at every comma, so the text splits at each one;
%   and as no element starts with a quote nor has an escape,
%   cleanValue only trims the spaces around it.  A text that starts a
%   quoted run and never ends it has an odd number of parts between
%   quotes, and fails.  Fails on anything else.

one_quote_elements(Inner, Elements) :-
    quote_specials(Specials),
    one_part(Inner, Specials),
    (   \+ sub_atom_icasechk(Inner, _, "'")
    ->  Quote = "\""
    ;   \+ sub_atom_icasechk(Inner, _, "\"")
    ->  Quote = "'"
    ),
    split_string(Inner, Quote, "", [Before|Runs]),
    \+ opens_first(Before),
    quoted_runs(Runs),
    split_string(Inner, ",", " ", Elements).

%   opens_first(+Before): the quote after Before, the text before the
%   first quote, starts an element.  opens_next(+Between): so does the
%   quote after Between, the text between a quoted run and the next.

opens_first(Before) :-
    split_string(Before, "", " ", [Trimmed]),
    (   Trimmed == ""
    ->  true
    ;   sub_string(Trimmed, _, 1, 0, ",")
    ).

opens_next(Between) :-
    split_string(Between, "", " ", [Trimmed]),
    sub_string(Trimmed, _, 1, 0, ",").

%   quoted_runs(+Runs): Runs are the inside of a quoted run, what comes
%   after it, and so on; no inside has a comma, no quote but the first
%   opens an element.

quoted_runs([Inside, After|Runs]) :-
    \+ sub_atom_icasechk(Inside, _, ","),
    (   Runs == []
    ->  true
    ;   \+ opens_next(After),
        quoted_runs(Runs)
    ).

%   opening_quote(+Inner, -Code): the first character of Inner that is
%   not a space (the clients write none).

opening_quote(Inner, Code) :-
    code_at(1, Inner, Code0),
    (   Code0 == 0'\s
    ->  split_string(Inner, "", " ", [Trimmed]),
        code_at(1, Trimmed, Code)
    ;   Code = Code0
    ).

quote_pair(0'", "\"", "'").
quote_pair(0'\', "'", "\"").

escaped_quote(Quote, Text) :-
    sub_string(Text, 0, 1, _, Quote).

%   quoted_parts(+Parts, +Q, -Elements): Parts, the pieces of the text
%   between quotes, are an element, what separates it from the next,
%   and so on.  An element is several pieces where a piece ends with
%   the backslash escaping the quote after it.  Q holds the quote,
%   whether the text has escapes, the other quote and whether the text
%   has it.

quoted_parts(Parts0, Q, [Element|Elements]) :-
    quoted_element(Parts0, Q, Element, [Between|Parts]),
    (   arg(4, Q, true)
    ->  arg(3, Q, Other),
        split_string(Element, Other, "", OtherParts),
        length(OtherParts, N),
        N mod 2 =:= 1                       % the other quote: even times
    ;   true
    ),
    (   Parts == []
    ->  split_string(Between, "", " ", [""]),
        Elements = []
    ;   comma(Between),
        quoted_parts(Parts, Q, Elements)
    ).

quoted_element(Parts0, Q, Element, Parts) :-
    element_pieces(Parts0, Q, Pieces, Parts),
    (   Pieces = [Element]
    ->  true
    ;   arg(1, Q, Quote),
        Pieces = [First|Rest],
        foldl(quote_before(Quote), Rest, Joined, []),
        atomics_to_string([First|Joined], Element)  % once: linear
    ).

quote_before(Quote, Piece, [Quote, Piece|Tail], Tail).

%   element_pieces(+Parts0, +Q, -Pieces, -Parts): Pieces are the
%   pieces of one element, each backslash escaping a quote taken off;
%   the element is Pieces joined by the quote.

element_pieces([Piece|Parts0], Q, Pieces, Parts) :-
    (   arg(2, Q, true),
        sub_string(Piece, Length, 1, 0, "\\")
    ->  sub_string(Piece, 0, Length, _, Head),
        Pieces = [Head|Pieces1],
        element_pieces(Parts0, Q, Pieces1, Parts)
    ;   Pieces = [Piece],
        Parts = Parts0
    ).

comma(Between) :-
    (   Between == ","
    ->  true
    ;   Between == ", "
    ->  true
    ;   split_string(Between, "", " ", [","])
    ).

%   general_elements(+Inner, -Elements): the elements of the non-empty
%   inside of a collection, the general way.

general_elements(Inner, Elements) :-
    tokenize(Inner, 0',, Tokens),
    maplist(clean_value, Tokens, Elements).

null_text(Text) :-
    string_length(Text, Len),
    (   Len =:= 0
    ->  true
    ;   Len =:= 4,
        string_lower(Text, "null")
    ).

%!  oro_parse_map(+Text, -Pairs:list(pair(string,string))) is det.
%
%   Decode a `Map<String,String>` parameter `{k1:v1, k2:v2}` into
%   `Key-Value` pairs of strings, in the order written.  Braces are
%   required; `{}` gives `[]`.  Entries are split on `,` by
%   oro_tokenize/3; each must contain `:` and is split at its first `:`
%   (quotes are not honoured for the colon); key and value go through
%   oro_clean_value/2.
%
%   @error type_error(oro_map, Text) if Text is not framed by `{ }` or an
%          entry has no `:`.

oro_parse_map(Text, Pairs) :-
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, map_pairs(Text, Pairs)).

map_pairs(Text, Pairs) :-
    (   framed(Text, 0'{, 0'}, Inner)
    ->  (   Inner == ""
        ->  Pairs = []
        ;   tokenize(Inner, 0',, Tokens),
            maplist(map_entry(Text), Tokens, Pairs)
        )
    ;   throw(error(type_error(oro_map, Text), _))
    ).

map_entry(Text, Token, Key-Value) :-
    (   sub_string(Token, Before, 1, After, ":")
    ->  sub_string(Token, 0, Before, _, KeyText),
        sub_string(Token, _, After, 0, ValueText),
        clean_value(KeyText, Key),
        clean_value(ValueText, Value)
    ;   throw(error(type_error(oro_map, Text), _))
    ).


                 /*******************************
                 *          STATEMENTS          *
                 *******************************/

%!  oro_parse_statement(+Text, -Triple) is det.
%
%   Parse a complete or partial statement `subject predicate object`
%   into `rdf(S, P, O)`.  Text is trimmed and split on single spaces by
%   oro_tokenize/3.  A token `?name` gives `var(name)` in any position;
%   other subjects and predicates are names expanded by oro_name_iri/2;
%   other objects follow ORO's literal rules (see the module doc) and
%   give an rdf_db literal term or an IRI.
%
%   @error syntax_error(oro_statement_tokens(N, Stmt)) unless there are
%          exactly three tokens; Stmt is the trimmed text (a string).
%   @error syntax_error(oro_statement_empty_token(Stmt)) if one of the
%          three tokens is empty.
%   @error syntax_error(oro_statement_variable(Stmt)) for a bare `?`.
%   @error type_error(oro_statement, Stmt) if a token leaves a quote
%          open (`a b "c d`: a `"` or `'` not closed by one of the same
%          kind, an escaped one not counting), or if an object opens
%          with a quote but is neither a string, a language-tagged nor
%          a typed literal (`"abc"def`).
%   @error syntax_error(oro_invalid_datatype(Type)) for `lex^^type`
%          with an unknown XSD datatype.
%   @error syntax_error(oro_lexical_form(Lex, Type)) for `lex^^type`
%          whose lexical form is not valid for the datatype.

oro_parse_statement(Text, Triple) :-
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, parse_statement(Text, Triple)).

%!  oro_parse_statements(+Texts, -Triples) is det.
%
%   Parse a list of statement texts with oro_parse_statement/2.  The
%   first statement in error raises its error.

oro_parse_statements(Texts, Triples) :-
    must_be(list(text), Texts),
    texts_size(Texts, Size),
    bounded(Size, maplist(parse_statement, Texts, Triples)).

%!  oro_is_partial(+Triple) is semidet.
%
%   True if at least one position of Triple (`rdf(S, P, O)` as made by
%   oro_parse_statement/2) is a variable `var(Name)`.
%
%   @error type_error(oro_triple, Triple) if Triple is not `rdf/3`.

oro_is_partial(Triple) :-
    (   compound(Triple),
        compound_name_arity(Triple, rdf, 3)
    ->  true
    ;   type_error(oro_triple, Triple)
    ),
    Triple = rdf(S, P, O),
    (   is_var_term(S)
    ->  true
    ;   is_var_term(P)
    ->  true
    ;   is_var_term(O)
    ).

is_var_term(Term) :-
    subsumes_term(var(_), Term).

%   parse_statement(+Text, -Triple).  Three fast paths before the
%   general one:
%
%     - local_statement/2: a plain text (see plain_text/1) without any
%       of `:#<^@`, made of three non-empty tokens separated by single
%       spaces with no space around.  Its subject and predicate are
%       names of the default namespace or variables, and so is its
%       object unless it does not start with a letter or is a boolean.
%       Two splits find all that.
%     - plain_statement_tokens/4: a plain text of three non-empty tokens
%       separated by single spaces, with no space around: the text is
%       the statement already trimmed and tokenized.
%     - literal_statement/2: two such tokens, then a literal in
%       double quotes that ends the text (`obj1 rdfs:label "table 2"`),
%       with no quote, backslash, bracket, brace or control character
%       inside: the tokenizer would not split it, and it needs no
%       unescaping.
%
%   Anything else (two spaces, a tab, quotes...) goes through
%   general_statement/2, which also raises the errors.

parse_statement(Text, Triple) :-
    (   local_statement(Text, Triple0)
    ->  Triple = Triple0
    ;   plain_statement_tokens(Text, ST, PT, OT)
    ->  tokens_triple(ST, PT, OT, Text, Triple)
    ;   literal_statement(Text, Triple0)
    ->  Triple = Triple0
    ;   general_statement(Text, Triple)
    ).

local_statement(Text, rdf(S, P, O)) :-
    local_specials(Specials),
    one_part(Text, Specials),
    split_string(Text, " ", "", [ST, PT, OT]),
    ST \== "",
    PT \== "",
    OT \== "",
    local_token(ST, Text, S),
    local_token(PT, Text, P),
    local_object_token(OT, Text, O).

plain_statement_tokens(Text, ST, PT, OT) :-
    plain_text(Text),
    split_string(Text, " ", "", [ST, PT, OT]),
    ST \== "",
    PT \== "",
    OT \== "".

literal_statement(Text, rdf(S, P, O)) :-
    sub_string(Text, _, 1, 0, "\""),       % not a typed or tagged one
    split_string(Text, "\"", "", [Head, Inner, ""]),
    split_string(Head, " ", "", [ST, PT, ""]),
    ST \== "",
    PT \== "",
    plain_text(Head),
    quote_specials(Specials),
    one_part(Inner, Specials),
    resource_token(ST, Text, S),
    resource_token(PT, Text, P),
    string_literal(Inner, O).

%!  general_statement(+Text, -Triple) is det.
%
%   Parse a statement the general way: trim, tokenize, then decide
%   every token.  parse_statement/2 gives the same result faster on the
%   texts its fast paths accept (the tests compare both).

general_statement(Text, Triple) :-
    statement_tokens(Text, Stmt, ST, PT, OT),
    tokens_triple(ST, PT, OT, Stmt, Triple).

tokens_triple(ST, PT, OT, Stmt, rdf(S, P, O)) :-
    resource_token(ST, Stmt, S),
    resource_token(PT, Stmt, P),
    object_token(OT, Stmt, O),
    bracket_free_name(ST, S),
    bracket_free_name(PT, P),
    bracket_free_name(OT, O).

%   bracket_free_name(+Token, +Term): unless Term is a name written
%   without `<...>`, Token has no bracket nor brace: `[x]` or `{x}` is
%   the leftover of a collection, not a name to store.

bracket_free_name(Token, Term) :-
    (   atom(Term),
        \+ string_code(1, Token, 0'<),
        \+ split_string(Token, "[]{}", "", [_])
    ->  string_from_text(Token, String),
        throw(error(syntax_error(oro_statement_name(String)), _))
    ;   true
    ).

%   local_token(+Token, +Stmt, -Term) and local_object_token(+Token,
%   +Stmt, -Term): as resource_token/3 and object_token/3 for a plain
%   token without `:#<^@`: a name needs no further check.

local_token(Token, Stmt, Term) :-
    (   string_code(1, Token, 0'?)
    ->  variable_token(Token, Stmt, Term)
    ;   oro_default_namespace(NS),
        atom_concat(NS, Token, Term)
    ).

local_object_token(Token, Stmt, Term) :-
    string_code(1, Token, C),
    (   C == 0'?
    ->  variable_token(Token, Stmt, Term)
    ;   name_start(C),
        Token \== "true",
        Token \== "false"
    ->  oro_default_namespace(NS),
        atom_concat(NS, Token, Term)
    ;   string_codes(Token, Codes),
        object_codes(Codes, Token, Term)
    ).

statement_tokens(Text, Stmt, ST, PT, OT) :-
    trim(Text, Stmt),
    tokenize(Stmt, 0'\s, Tokens),
    (   Tokens = [ST, PT, OT]
    ->  true
    ;   length(Tokens, N),
        throw(error(syntax_error(oro_statement_tokens(N, Stmt)), _))
    ),
    (   ( ST == "" ; PT == "" ; OT == "" )
    ->  throw(error(syntax_error(oro_statement_empty_token(Stmt)), _))
    ;   true
    ),
    (   member(Token, [ST, PT, OT]),
        \+ quotes_closed(Token)
    ->  quote_error(Stmt)
    ;   true
    ).

%   quotes_closed(+Token): every quote Token opens is closed in it.  A
%   `"` or `'` opens a quoted run, which ends at the next quote of the
%   same kind (the other kind is plain text inside it); a `\` escapes
%   the next character, inside a run or not, as in unescape_codes/3.
%   So `"it's"`, `'say "hi"'` and `a\"b` are closed; `"abc`, `x"`,
%   `john's` and `"a\"` are not.  Only the last token of a statement
%   can fail this: the tokenizer does not split inside quotes.

quotes_closed(Token) :-
    (   split_string(Token, "\"'", "", [_])
    ->  true                                % no quote at all
    ;   string_codes(Token, Codes),
        closed_codes(Codes)
    ).

closed_codes([]).
closed_codes([C|Cs]) :-
    (   C == 0'\\
    ->  (   Cs = [_|Cs1]
        ->  closed_codes(Cs1)
        ;   true
        )
    ;   quote_code(C)
    ->  quoted_run(Cs, C, Rest),
        closed_codes(Rest)
    ;   closed_codes(Cs)
    ).

%   quoted_run(+Codes, +Quote, -Rest): Codes starts inside a run opened
%   by Quote; Rest follows the quote that closes it.  Fails if none does.

quoted_run([C|Cs], Q, Rest) :-
    (   C == Q
    ->  Rest = Cs
    ;   C == 0'\\
    ->  Cs = [_|Cs1],
        quoted_run(Cs1, Q, Rest)
    ;   quoted_run(Cs, Q, Rest)
    ).

%   quote_error(+Stmt): Stmt has a token with an unterminated quote, or
%   an object token opening with a quote that is not a literal.  The
%   error is the one server/oro_errors.pl maps to ORO's
%   IllegalStatementException for a text that is not a statement.

quote_error(Stmt) :-
    string_from_text(Stmt, String),
    throw(error(type_error(oro_statement, String), _)).

%   resource_token(+Token, +Stmt, -Term) and object_token(+Token, +Stmt,
%   -Term): Token is not empty; Stmt is the statement (for errors).
%
%   An object token that starts with a letter, is not a boolean and
%   has no `^` nor `@` can only be a name (so neither a typed nor a
%   language-tagged literal): the common case, on the hot path of every
%   add.  Other tokens are decided by object_codes/3, which gives names
%   too.

resource_token(Token, Stmt, Term) :-
    (   string_code(1, Token, 0'?)
    ->  variable_token(Token, Stmt, Term)
    ;   oro_name_iri(Token, Term)
    ).

variable_token(Token, Stmt, var(Name)) :-
    sub_atom(Token, 1, _, 0, Name),
    (   Name == ''
    ->  string_from_text(Stmt, StmtString),
        throw(error(syntax_error(oro_statement_variable(StmtString)), _))
    ;   true
    ).

object_token(Token, Stmt, Term) :-
    string_code(1, Token, C),
    (   C == 0'?
    ->  variable_token(Token, Stmt, Term)
    ;   name_start(C),
        Token \== "true",
        Token \== "false"
    ->  (   split_string(Token, ":#<^@", "", [_])
        ->  oro_default_namespace(NS),
            atom_concat(NS, Token, Term)
        ;   split_string(Token, "^@", "", [_])
        ->  oro_name_iri(Token, Term)
        ;   string_codes(Token, Codes),
            object_codes(Codes, Token, Term)
        )
    ;   string_codes(Token, Codes),
        object_codes(Codes, Token, Term0),
        (   atom(Term0),
            quote_code(C)
        ->  quote_error(Stmt)               % "abc"def, "x"@, 'a'b
        ;   Term = Term0
        )
    ).

%   name_start(+Code): Code may start a name: a letter (code_type/2
%   `alpha` less digits and `_`), decided by arithmetic for ASCII.

name_start(C) :-
    (   C < 128
    ->  (   C >= 0'a
        ->  C =< 0'z
        ;   C >= 0'A,
            C =< 0'Z
        )
    ;   code_type(C, alpha),
        \+ code_type(C, digit)
    ).


                 /*******************************
                 *        API STATEMENTS        *
                 *******************************/

%!  oro_statements(+Statements, -Triples, -Bindings) is det.
%
%   Normalise Statements (text or rdf/3 terms, see the module doc)
%   into rdf(S,P,O) triples of IRIs, literals and variables.  Bindings
%   maps the names of `?name` variables of text patterns to the
%   variables of Triples, as Name=Var pairs; variables with the same
%   name in several statements are shared.
%
%   @error syntax_error(oro_statement_tokens(N, Text)) and the other
%          errors of oro_parse_statement/2.

oro_statements(Statements, Triples, Bindings) :-
    must_be(list, Statements),
    texts_size(Statements, Size),
    bounded(Size, statement_triples(Statements, Triples, [], Bindings0)),
    reverse(Bindings0, Bindings).

%!  oro_complete_statements(+Statements, -Triples) is det.
%
%   As oro_statements/3, for Statements that must all be complete (no
%   variable) and make sense as facts: the statements a change asserts,
%   or a hypothesis.  A literal cannot be the object of a predicate of
%   RDF, RDFS or OWL whose object is a class, a property or an
%   individual (`Fork rdfs:subClassOf "x"`, `fork1 owl:sameAs 3`).
%
%   @error syntax_error(oro_statement_incomplete(Text)) if the first
%          of them that is not a fact is a pattern, Text showing it as
%          the client wrote it: its text, trimmed, or the light form of
%          a term (`x ?_ y`).
%   @error syntax_error(oro_statement_literal(Text)) if it has a
%          literal where a resource is needed.
%   @error the errors of oro_statements/3.

oro_complete_statements(Statements, Triples) :-
    oro_statements(Statements, Triples, _),
    (   first_bad(Statements, Triples, Statement, Triple, Kind)
    ->  statement_display(Statement, Triple, Text),
        bad_statement(Kind, Text, Formal),
        throw(error(syntax_error(Formal), _))
    ;   true
    ).

first_bad([Statement0|Statements], [Triple0|Triples],
          Statement, Triple, Kind) :-
    (   bad_triple(Triple0, Kind0)
    ->  Statement = Statement0,
        Triple = Triple0,
        Kind = Kind0
    ;   first_bad(Statements, Triples, Statement, Triple, Kind)
    ).

bad_triple(Triple, pattern) :-
    \+ ground(Triple),
    !.
bad_triple(rdf(_, P, literal(_)), literal) :-
    resource_object(P).

bad_statement(pattern, Text, oro_statement_incomplete(Text)).
bad_statement(literal, Text, oro_statement_literal(Text)).

%   resource_object(?P): the object of P is a class, a property, an
%   individual or a list of them, never a literal.

:- rdf_meta resource_object(r).

resource_object(rdf:type).
resource_object(rdfs:subClassOf).
resource_object(rdfs:subPropertyOf).
resource_object(rdfs:domain).
resource_object(rdfs:range).
resource_object(owl:equivalentClass).
resource_object(owl:equivalentProperty).
resource_object(owl:sameAs).
resource_object(owl:differentFrom).
resource_object(owl:inverseOf).
resource_object(owl:disjointWith).
resource_object(owl:propertyDisjointWith).
resource_object(owl:complementOf).
resource_object(owl:onProperty).
resource_object(owl:someValuesFrom).
resource_object(owl:allValuesFrom).
resource_object(owl:onClass).
resource_object(owl:intersectionOf).
resource_object(owl:unionOf).
resource_object(owl:oneOf).
resource_object(owl:propertyChainAxiom).
resource_object(owl:members).
resource_object(owl:distinctMembers).
resource_object(owl:disjointUnionOf).

%   statement_display(+Statement, +Triple, -Text): Text (a string)
%   shows Statement to the client who gave it.

statement_display(Statement, rdf(S, P, O), Text) :-
    (   atomic(Statement)                   % a string or an atom
    ->  split_string(Statement, "", " \t\r\n", [Text])
    ;   maplist(position_display, [S, P, O], Parts),
        atomic_list_concat(Parts, ' ', Atom),
        atom_string(Atom, Text)
    ).

position_display(Term, Text) :-
    (   var(Term)
    ->  Text = '?_'
    ;   oro_term_light_text(Term, Text)
    ).

statement_triples([], [], B, B).
statement_triples([Statement|Statements], [Triple|Triples], B0, B) :-
    statement_triple(Statement, Triple, B0, B1),
    statement_triples(Statements, Triples, B1, B).

statement_triple(Statement, rdf(S, P, O), B0, B) :-
    (   statement_text(Statement)
    ->  parse_statement(Statement, rdf(S0, P0, O0)),
        bind_var(S0, S, B0, B1),
        bind_var(P0, P, B1, B2),
        bind_var(O0, O, B2, B)
    ;   var(Statement)
    ->  instantiation_error(Statement)
    ;   Statement = rdf(S0, P0, O0)
    ->  oro_resource(S0, S),
        oro_resource(P0, P),
        oro_object(O0, O),
        term_literal_check(O0, O),
        B = B0
    ;   type_error(oro_statement, Statement)
    ).

%   term_literal_check(+Term, +Object): a typed literal written as such
%   in a term statement (Term, normalised as Object) has a lexical form
%   its datatype accepts, as in a text statement (check_datatype/3).
%   Numbers are typed as the parser types number tokens.

term_literal_check(Term, Object) :-
    (   nonvar(Term),
        (   Term = literal(_)
        ;   Term = _^^_
        ),
        Object = literal(type(Type, Lex))
    ->  lexical_verdict(Type, Lex, Verdict),
        (   Verdict == ok
        ->  true
        ;   oro_iri_name(Type, TypeText),       % named for the error only
            atom_string(Lex, LexString),
            datatype_verdict(Verdict, LexString, TypeText)
        )
    ;   true
    ).

statement_text(X) :-
    (   string(X)
    ->  true
    ;   atom(X)
    ).

%   bind_var(+Parsed, -Term, +Bindings0, -Bindings): Term is Parsed,
%   or for var(Name) the variable bound to Name (a new one if Name is
%   not in Bindings0 yet).

bind_var(Parsed, Term, B0, B) :-
    (   Parsed = var(Name)
    ->  (   memberchk(Name=Var0, B0)
        ->  Term = Var0,
            B = B0
        ;   B = [Name=Term|B0]
        )
    ;   Term = Parsed,
        B = B0
    ).
