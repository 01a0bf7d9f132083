:- module(oro_parse_literal,
          [ object_codes/3,             % +Codes, +Token, -Term
            string_literal/2,           % +LexString, -Literal
            lexical_verdict/3,          % +Type, +LexText, -Verdict
            datatype_verdict/3          % +Verdict, +LexText, +TypeText
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/parse/oro_parse_lexer)).

/** <module> ORO's literal rules and the lexical forms of XSD datatypes

This module owns what an object token means when it is not a plain
name: ORO's `parseLiteral` (object_codes/3), in order a typed literal
`lex^^type`, a boolean, a quoted string, a language-tagged string
`"text"@lang`, an integer, a double, else a resource.  A typed
literal's lexical form is checked against its XSD datatype
(lexical_verdict/3): the table of the datatypes oro accepts and the
grammars of their lexical forms (numbers, binary encodings, dates,
times and durations) are here.  Lexical forms are kept as written, as
atoms.

The statement syntax (oro_parse_statement) calls object_codes/3 for
the object tokens it cannot decide at once, and lexical_verdict/3 and
datatype_verdict/3 for typed literals given as terms.
*/

%!  object_codes(+Codes:list(code), +Token:string, -Term) is det.
%
%   ORO's parseLiteral, in order: typed literal, boolean, quoted
%   string, language-tagged string, integer, double, resource.  Term is
%   an rdf_db literal term or an IRI.
%
%   @error syntax_error(oro_invalid_datatype(Type)) for `lex^^type`
%          with an unknown XSD datatype or an empty one.
%   @error syntax_error(oro_lexical_form(Lex, Type)) for `lex^^type`
%          whose lexical form the datatype rejects.
%   @error syntax_error(oro_unicode_escape(Token)) for a malformed
%          `\uXXXX` escape inside quotes.

object_codes(Codes, Token, Term) :-
    (   typed_split(Codes, LexCodes, TypeCodes)
    ->  typed_literal(LexCodes, TypeCodes, Term)
    ;   Token == "true"
    ->  rdf_equal(Type, xsd:boolean),
        Term = literal(type(Type, true))
    ;   Token == "false"
    ->  rdf_equal(Type, xsd:boolean),
        Term = literal(type(Type, false))
    ;   quoted(Token, _)
    ->  sub_string(Token, 1, _, 1, Inner),
        unescape(Inner, Token, LexString),
        string_literal(LexString, Term)
    ;   lang_split(Codes, LexCodes, Lang)
    ->  unescape_codes(LexCodes, Token, Unescaped),
        atom_codes(Lex, Unescaped),
        Term = literal(lang(Lang, Lex))
    ;   integer_lexical(Codes)
    ->  atom_codes(Lex, Codes),
        rdf_equal(Type, xsd:int),
        Term = literal(type(Type, Lex))
    ;   decimal_lexical(Codes, true)
    ->  atom_codes(Lex, Codes),
        rdf_equal(Type, xsd:double),
        Term = literal(type(Type, Lex))
    ;   oro_name_iri(Token, Term)
    ).

%!  string_literal(+LexString:string, -Literal) is det.
%
%   Literal is the xsd:string literal of LexString (unescaped), as a
%   quoted object token gives it.

string_literal(LexString, literal(type(Type, Lex))) :-
    atom_string(Lex, LexString),
    rdf_equal(Type, xsd:string).

%   typed_split(+Codes, -Lex, -Type): split at the last `^^` that has
%   no quote after it, i.e. the last `^^` outside the quoted lexical
%   form.  Types never contain quotes; deciding from the right keeps an
%   apostrophe inside `"it's"^^xsd:string` from hiding the separator.

typed_split(Codes, Lex, Type) :-
    memberchk(0'^, Codes),
    last_separator(Codes, 0, none, Pos),
    integer(Pos),
    length(Lex, Pos),
    append(Lex, [0'^, 0'^|Type], Codes).

last_separator([], _, Pos, Pos).
last_separator([C|Cs], I, Pos0, Pos) :-
    (   C == 0'^,
        Cs = [0'^|_]
    ->  Pos1 = I
    ;   quote_code(C)
    ->  Pos1 = none
    ;   Pos1 = Pos0
    ),
    I1 is I+1,
    last_separator(Cs, I1, Pos1, Pos).

typed_literal(LexCodes0, TypeCodes0, literal(type(Type, Lex))) :-
    string_codes(LexText, LexCodes0),
    string_codes(TypeText, TypeCodes0),
    (   quoted(LexText, _)
    ->  sub_string(LexText, 1, _, 1, Inner),
        unescape(Inner, LexText, LexString)
    ;   LexString = LexText
    ),
    (   framed(TypeText, 0'<, 0'>, TypeName)
    ->  true
    ;   TypeName = TypeText
    ),
    (   TypeName == ""
    ->  throw(error(syntax_error(oro_invalid_datatype(TypeText)), _))
    ;   true
    ),
    oro_name_iri(TypeName, Type),
    check_datatype(Type, LexString, TypeText),
    atom_string(Lex, LexString).

check_datatype(Type, LexString, TypeText) :-
    lexical_verdict(Type, LexString, Verdict),
    datatype_verdict(Verdict, LexString, TypeText).

%!  lexical_verdict(+Type:atom, +LexText, -Verdict:atom) is det.
%!  datatype_verdict(+Verdict:atom, +LexText:string, +TypeText) is det.
%
%   lexical_verdict/3: whether LexText is a lexical form of the datatype
%   Type: `ok` (or a datatype out of the XSD namespace, not checked),
%   `bad_form`, or `bad_datatype` (an XSD name that is no datatype).
%   datatype_verdict/3 raises the syntax error of a bad one, naming
%   the type as the statement did, and succeeds on `ok`.
%
%   @error syntax_error(oro_lexical_form(LexText, TypeText)) for
%          `bad_form`.
%   @error syntax_error(oro_invalid_datatype(TypeText)) for
%          `bad_datatype`.

lexical_verdict(Type, LexText, Verdict) :-
    oro_prefix(xsd, NS),
    (   atom_concat(NS, Local, Type)
    ->  (   xsd_lexical(Local, Check)
        ->  string_codes(LexText, Codes),
            (   lexical_ok(Check, Codes)
            ->  Verdict = ok
            ;   Verdict = bad_form
            )
        ;   Verdict = bad_datatype
        )
    ;   Verdict = ok
    ).

datatype_verdict(ok, _, _).
datatype_verdict(bad_form, LexText, TypeText) :-
    throw(error(syntax_error(oro_lexical_form(LexText, TypeText)), _)).
datatype_verdict(bad_datatype, _, TypeText) :-
    throw(error(syntax_error(oro_invalid_datatype(TypeText)), _)).

%   lang_split(+Codes, -LexCodes, -Lang): Codes is `"lex"@lang` or
%   `'lex'@lang`.  LexCodes is the text between the quotes.

lang_split([Q|Codes], Lex, Lang) :-
    quote_code(Q),
    memberchk(0'@, Codes),
    reverse(Codes, Reversed),
    append(RevTag, [0'@, Q|RevLex], Reversed),
    !,
    RevTag \== [],
    reverse(RevTag, TagCodes),
    lang_tag(TagCodes),
    reverse(RevLex, Lex),
    atom_codes(Lang, TagCodes).

lang_tag(Codes) :-
    phrase(lang_tag, Codes).

lang_tag -->
    alphas(1),
    lang_subtags.

lang_subtags --> [].
lang_subtags -->
    "-",
    alnums(1),
    lang_subtags.

alphas(N) -->
    [C],
    { code_type(C, alpha), C < 128, C \== 0'_ },
    !,
    { N1 is N-1 },
    alphas(N1).
alphas(N) -->
    { N =< 0 }.

alnums(N) -->
    [C],
    { code_type(C, alnum), C < 128 },
    !,
    { N1 is N-1 },
    alnums(N1).
alnums(N) -->
    { N =< 0 }.


                 /*******************************
                 *       LEXICAL FORMS          *
                 *******************************/

%   xsd_lexical(?Local, ?Check): the XSD datatypes oro accepts in
%   `lex^^xsd:Local` and how their lexical forms are checked.

xsd_lexical(string,             any).
xsd_lexical(normalizedString,   any).
xsd_lexical(token,              any).
xsd_lexical(language,           any).
xsd_lexical('NMTOKEN',          any).
xsd_lexical('NMTOKENS',         any).
xsd_lexical('Name',             any).
xsd_lexical('NCName',           any).
xsd_lexical('ID',               any).
xsd_lexical('IDREF',            any).
xsd_lexical('IDREFS',           any).
xsd_lexical('ENTITY',           any).
xsd_lexical('ENTITIES',         any).
xsd_lexical('QName',            any).
xsd_lexical('NOTATION',         any).
xsd_lexical(anyURI,             any).
xsd_lexical(base64Binary,       base64).
xsd_lexical(hexBinary,          hex).
xsd_lexical(boolean,            boolean).
xsd_lexical(decimal,            decimal).
xsd_lexical(double,             double).
xsd_lexical(float,              double).
xsd_lexical(integer,            integer(inf, inf)).
xsd_lexical(nonPositiveInteger, integer(inf, 0)).
xsd_lexical(negativeInteger,    integer(inf, -1)).
xsd_lexical(nonNegativeInteger, integer(0, inf)).
xsd_lexical(positiveInteger,    integer(1, inf)).
xsd_lexical(long,               integer(-9223372036854775808, 9223372036854775807)).
xsd_lexical(int,                integer(-2147483648, 2147483647)).
xsd_lexical(short,              integer(-32768, 32767)).
xsd_lexical(byte,               integer(-128, 127)).
xsd_lexical(unsignedLong,       integer(0, 18446744073709551615)).
xsd_lexical(unsignedInt,        integer(0, 4294967295)).
xsd_lexical(unsignedShort,      integer(0, 65535)).
xsd_lexical(unsignedByte,       integer(0, 255)).
xsd_lexical(dateTime,           grammar(date_time(optional))).
xsd_lexical(dateTimeStamp,      grammar(date_time(required))).
xsd_lexical(date,               grammar(date)).
xsd_lexical(time,               grammar(time)).
xsd_lexical(gYear,              grammar(g_year)).
xsd_lexical(gYearMonth,         grammar(g_year_month)).
xsd_lexical(gMonth,             grammar(g_month)).
xsd_lexical(gMonthDay,          grammar(g_month_day)).
xsd_lexical(gDay,               grammar(g_day)).
xsd_lexical(duration,           grammar(duration)).
xsd_lexical(dayTimeDuration,    grammar(duration)).
xsd_lexical(yearMonthDuration,  grammar(duration)).

lexical_ok(any, _).
lexical_ok(boolean, Codes) :-
    memberchk(Codes, [`true`, `false`, `1`, `0`]).
lexical_ok(decimal, Codes) :-
    (   decimal_lexical(Codes, false)
    ->  true
    ;   integer_lexical(Codes)              % "1"^^xsd:decimal
    ).
lexical_ok(double, Codes) :-
    (   memberchk(Codes, [`INF`, `+INF`, `-INF`, `NaN`])
    ->  true
    ;   decimal_lexical(Codes, true)
    ;   integer_lexical(Codes)
    ).
lexical_ok(integer(Min, Max), Codes) :-
    integer_lexical(Codes),
    (   Codes = [0'+|Digits]
    ->  number_codes(Value, Digits)
    ;   number_codes(Value, Codes)
    ),
    (   Min == inf
    ->  true
    ;   Value >= Min
    ),
    (   Max == inf
    ->  true
    ;   Value =< Max
    ).
lexical_ok(hex, Codes) :-
    length(Codes, Len),
    Len mod 2 =:= 0,
    forall(member(C, Codes), code_type(C, xdigit(_))).
lexical_ok(base64, Codes) :-
    forall(member(C, Codes), base64_code(C)).
lexical_ok(grammar(Grammar), Codes) :-
    phrase(Grammar, Codes),
    !.

base64_code(C) :-
    (   code_type(C, alnum),
        C < 128
    ->  true
    ;   memberchk(C, `+/= `)
    ).

%   integer_lexical(+Codes): `[+-]?[0-9]+`

integer_lexical(Codes) :-
    (   Codes = [S|Digits],
        sign_code(S)
    ->  true
    ;   Digits = Codes
    ),
    digits1(Digits, []).

sign_code(0'+).
sign_code(0'-).

%   decimal_lexical(+Codes, +Exponent): `[+-]?(D+(.D*)?|.D+)`, followed
%   by `[eE][+-]?D+` if Exponent is `true`, and not a plain integer
%   unless there is an exponent.

decimal_lexical(Codes, Exponent) :-
    (   Codes = [S|Codes1],
        sign_code(S)
    ->  true
    ;   Codes1 = Codes
    ),
    mantissa(Codes1, Rest, Dot),
    (   Rest == []
    ->  Dot == true
    ;   Exponent == true,
        Rest = [E|Rest1],
        memberchk(E, `eE`),
        (   Rest1 = [S1|Rest2],
            sign_code(S1)
        ->  true
        ;   Rest2 = Rest1
        ),
        digits1(Rest2, [])
    ).

mantissa([0'.|Cs], Rest, true) :-
    !,
    digits1(Cs, Rest).
mantissa(Cs, Rest, Dot) :-
    digits1(Cs, Rest0),
    (   Rest0 = [0'.|Rest1]
    ->  Dot = true,
        digits0(Rest1, Rest)
    ;   Dot = false,
        Rest = Rest0
    ).

digits1([C|Cs], Rest) :-
    digit_code(C),
    digits0(Cs, Rest).

digits0(Cs0, Rest) :-
    (   Cs0 = [C|Cs],
        digit_code(C)
    ->  digits0(Cs, Rest)
    ;   Rest = Cs0
    ).

digit_code(C) :-
    between(0'0, 0'9, C).

%   Grammars of the XSD date, time and duration types (lexical shape
%   and field ranges; day-of-month is not checked against the month).

date_time(Zone) -->
    date_part,
    "T",
    time_part,
    zone(Zone).

date -->
    date_part,
    zone(optional).

time -->
    time_part,
    zone(optional).

g_year -->
    year,
    zone(optional).

g_year_month -->
    year,
    "-",
    two(1, 12),
    zone(optional).

g_month -->
    "--",
    two(1, 12),
    zone(optional).

g_month_day -->
    "--",
    two(1, 12),
    "-",
    two(1, 31),
    zone(optional).

g_day -->
    "---",
    two(1, 31),
    zone(optional).

date_part -->
    year,
    "-",
    two(1, 12),
    "-",
    two(1, 31).

year -->
    optional_minus,
    digit,
    digit,
    digit,
    digit,
    digits_star.

time_part -->
    two(0, 24),
    ":",
    two(0, 59),
    ":",
    two(0, 59),
    fraction.

fraction -->
    ".",
    !,
    digit,
    digits_star.
fraction -->
    [].

zone(_) -->
    "Z",
    !.
zone(_) -->
    [S],
    { sign_code(S) },
    !,
    two(0, 14),
    ":",
    two(0, 59).
zone(optional) -->
    [].

duration -->
    optional_minus,
    "P",
    duration_fields([0'Y, 0'M, 0'D], 0, N0),
    (   "T"
    ->  duration_time_fields([0'H, 0'M, 0'S], 0, N1),
        { N1 > 0 }
    ;   { N1 = 0 }
    ),
    { N0 + N1 > 0 }.

duration_fields([], N, N) -->
    [].
duration_fields([Designator|Ds], N0, N) -->
    (   digit,
        digits_star,
        [Designator]
    ->  { N1 is N0+1 }
    ;   { N1 = N0 }
    ),
    duration_fields(Ds, N1, N).

duration_time_fields([], N, N) -->
    [].
duration_time_fields([Designator|Ds], N0, N) -->
    (   digit,
        digits_star,
        (   { Designator == 0'S }
        ->  fraction
        ;   []
        ),
        [Designator]
    ->  { N1 is N0+1 }
    ;   { N1 = N0 }
    ),
    duration_time_fields(Ds, N1, N).

optional_minus -->
    "-",
    !.
optional_minus -->
    [].

two(Min, Max) -->
    [A, B],
    { digit_code(A),
      digit_code(B),
      V is (A-0'0)*10 + B-0'0,
      between(Min, Max, V)
    }.

digit -->
    [C],
    { digit_code(C) }.

digits_star -->
    [C],
    { digit_code(C) },
    !,
    digits_star.
digits_star -->
    [].
