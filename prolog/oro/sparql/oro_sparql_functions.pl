:- module(oro_sparql_functions,
          [ eval_expr/4,                % +Expr, +Mu, +Ctx, -Value
            expr_true/3,                % +Expr, +Mu, +Ctx
            kind_type/2,                % ?Kind, ?Type
            cast_type/2                 % ?Type, ?Kind
          ]).
:- multifile
    pattern_exists/2.
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(uri)).
:- use_module(library(date)).
:- use_module(library(sha), [sha_hash/3, hash_atom/2]).
:- use_module(library(md5), [md5_hash/3]).
:- use_module(library(uuid), [uuid/2]).
:- use_module(library(oro/oro_names)).
:- if(exists_source(library(pcre))).
:- use_module(library(pcre)).
:- endif.
:- use_module(library(oro/sparql/oro_sparql_lexer), [digits//1]).
:- use_module(library(oro/sparql/oro_sparql_terms)).

/** <module> SPARQL expressions, functions, aggregates and datatypes

The value of SPARQL expressions in a solution: the three-valued logic
of `||` and `&&`, comparisons under the operator mapping of SPARQL 1.1
(numbers by value with type promotion, strings, booleans, dates), the
built-in functions, the XSD casts and the aggregates.  An error in an
expression makes it fail (a FILTER false, a BIND unbound).
*/

:- rdf_meta
    boolean_term(+, o),
    kind_type(?, r),
    cast_type(r, -),
    type_literal(r, +, -).

		 /*******************************
		 *           DATATYPES          *
		 *******************************/

%!  kind_type(?Kind, ?Type) is nondet.
%
%   Type is the XSD datatype of the numeric Kind (integer, decimal,
%   float, double).

kind_type(integer, xsd:integer).
kind_type(decimal, xsd:decimal).
kind_type(float,   xsd:float).
kind_type(double,  xsd:double).

%!  cast_type(?Type, ?Kind) is nondet.
%
%   Type is an XSD datatype SPARQL can cast to, Kind its kind.

cast_type(xsd:string, string).
cast_type(xsd:integer, integer).
cast_type(xsd:decimal, decimal).
cast_type(xsd:float, float).
cast_type(xsd:double, double).
cast_type(xsd:boolean, boolean).
cast_type(xsd:dateTime, dateTime).

type_literal(Type, Lex, literal(type(Type, Lex))).

kind_rank(integer, 0).
kind_rank(decimal, 1).
kind_rank(float, 2).
kind_rank(double, 3).

		 /*******************************
		 *          EXPRESSIONS         *
		 *******************************/

%   eval_expr(+Expr, +Mu, +Ctx, -Value) is semidet: failure is an
%   expression error (unbound variable, type error...).

%!  expr_true(+Expr, +Mu, +Ctx) is semidet.
%
%   The effective boolean value of Expr in Mu is true.

expr_true(E, Mu, Ctx) :-
    once(eval_expr(E, Mu, Ctx, V)),
    ebv(V, true).

%!  eval_expr(+Expr, +Mu, +Ctx, -Value) is semidet.
%
%   Value is the RDF term Expr evaluates to in the solution Mu; fails
%   on an expression error.

eval_expr(var(N), Mu, Ctx, V) :-
    !,
    lookup(N, Mu, Ctx, V).
eval_expr(const(T), _, _, T) :-
    !.
eval_expr(or(A, B), Mu, Ctx, V) :-
    !,
    truth(A, Mu, Ctx, TA),
    (   TA == true
    ->  R = true
    ;   truth(B, Mu, Ctx, TB),
        or3(TA, TB, R)
    ),
    boolean_term(R, V).
eval_expr(and(A, B), Mu, Ctx, V) :-
    !,
    truth(A, Mu, Ctx, TA),
    (   TA == false
    ->  R = false
    ;   truth(B, Mu, Ctx, TB),
        and3(TA, TB, R)
    ),
    boolean_term(R, V).
eval_expr(not(A), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    ebv(VA, B),
    negate(B, R),
    boolean_term(R, V).
eval_expr(cmp(Op, A, B), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    eval_expr(B, Mu, Ctx, VB),
    compare_values(Op, VA, VB, R),
    boolean_term(R, V).
eval_expr(in(A, L), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    membership(L, VA, Mu, Ctx, false, R),
    boolean_term(R, V).
eval_expr(not_in(A, L), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    membership(L, VA, Mu, Ctx, false, R0),
    negate(R0, R),
    boolean_term(R, V).
eval_expr(bound(N), Mu, Ctx, V) :-
    !,
    (   lookup(N, Mu, Ctx, _)
    ->  boolean_term(true, V)
    ;   boolean_term(false, V)
    ).
eval_expr(exists(P), Mu, Ctx, V) :-
    !,
    exists(P, Mu, Ctx, R),
    boolean_term(R, V).
eval_expr(not_exists(P), Mu, Ctx, V) :-
    !,
    exists(P, Mu, Ctx, R0),
    negate(R0, R),
    boolean_term(R, V).
eval_expr(fn(if, [C, A, B]), Mu, Ctx, V) :-
    !,
    eval_expr(C, Mu, Ctx, VC),
    ebv(VC, T),
    (   T == true
    ->  eval_expr(A, Mu, Ctx, V)
    ;   eval_expr(B, Mu, Ctx, V)
    ).
eval_expr(fn(coalesce, Args), Mu, Ctx, V) :-
    !,
    member(A, Args),
    eval_expr(A, Mu, Ctx, V),
    !.
eval_expr(agg(Name, Distinct, Arg, Sep), _, Ctx, V) :-
    !,
    Ctx = ctx(M, S, Members, C),
    Members \== none,
    aggregate_value(Name, Distinct, Arg, Sep, Members, ctx(M, S, none, C), V).
eval_expr(fn(bnode, [A]), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    simple_string(VA, Lex),
    labelled_bnode(Mu, Lex, V).
eval_expr(fn(Name, Args), Mu, Ctx, V) :-
    !,
    maplist(eval_arg(Mu, Ctx), Args, Vs),
    once(function(Name, Vs, V)).
eval_expr(E, Mu, Ctx, V) :-
    arithmetic(E, Mu, Ctx, V).

eval_arg(Mu, Ctx, E, V) :-
    eval_expr(E, Mu, Ctx, V).

%   truth(+E, +Mu, +Ctx, -T): T is true, false or error.

truth(E, Mu, Ctx, T) :-
    (   eval_expr(E, Mu, Ctx, V),
        ebv(V, B)
    ->  T = B
    ;   T = error
    ).

or3(true, _, true) :- !.
or3(_, true, true) :- !.
or3(false, false, false).

and3(false, _, false) :- !.
and3(_, false, false) :- !.
and3(true, true, true).

negate(true, false).
negate(false, true).

boolean_term(B, literal(type(xsd:boolean, B))).


%   membership(+List, +V, +Mu, +Ctx, +Error0, -R): IN with errors.

membership([], _, _, _, Error, R) :-
    Error == false,
    R = false.
membership([E|Es], V, Mu, Ctx, Error0, R) :-
    (   eval_expr(E, Mu, Ctx, VE),
        compare_values(=, V, VE, Eq)
    ->  (   Eq == true
        ->  R = true
        ;   membership(Es, V, Mu, Ctx, Error0, R)
        )
    ;   membership(Es, V, Mu, Ctx, true, R)
    ).

%!  pattern_exists(+Pattern, +Ctx) is semidet.
%
%   Hook: the annotated graph pattern Pattern has a solution in the
%   evaluation context Ctx.  oro_sparql_eval, the evaluator of graph
%   patterns, defines it: EXISTS calls back into the evaluator through
%   it, so that this module does not import the evaluator that imports
%   it.

exists(P, Mu, ctx(M, Subst0, _, C), R) :-
    merge_override(Mu, Subst0, Subst),
    (   pattern_exists(P, ctx(M, Subst, none, C))
    ->  R = true
    ;   R = false
    ).

merge_override(Mu, Subst0, Subst) :-
    findall(N-V, ( member(N-V, Subst0), \+ memberchk(N-_, Mu) ), Rest),
    append(Mu, Rest, Subst1),
    sort(1, @<, Subst1, Subst).

%   Effective boolean value (SPARQL 1.1 §17.2.2).

ebv(literal(type(T, Lex)), B) :-
    xsd_boolean(T),
    boolean_lexical(Lex, B0),
    !,
    B = B0.
ebv(T, B) :-
    value_class(T, C),
    ebv_class(C, B).

ebv_class(boolean(B), B).
ebv_class(string(Lex, _), B) :-
    (   Lex == ''
    ->  B = false
    ;   B = true
    ).
ebv_class(number(_, N), B) :-
    (   ( N =:= 0 ; N =\= N )
    ->  B = false
    ;   B = true
    ).
ebv_class(invalid(T, _), false) :-
    (   oro_numeric_datatype(T, _)
    ->  true
    ;   rdf_equal(T, xsd:boolean)
    ).

%   Comparisons (SPARQL 1.1 §17.3, the operator mapping).

compare_values(=, A, B, R) :-
    !,
    equal_terms(A, B, R).
compare_values('!=', A, B, R) :-
    !,
    equal_terms(A, B, R0),
    negate(R0, R).
compare_values(Op, A, B, R) :-
    value_class(A, CA),
    value_class(B, CB),
    order_class(CA, CB, Order),
    (   order_satisfies(Op, Order)
    ->  R = true
    ;   R = false
    ).

order_satisfies(<, <).
order_satisfies(>, >).
order_satisfies('<=', <).
order_satisfies('<=', =).
order_satisfies('>=', >).
order_satisfies('>=', =).

equal_terms(A, B, R) :-
    (   A == B
    ->  R = true
    ;   atom(A)
    ->  R = false
    ;   atom(B)
    ->  R = false
    ;   value_class(A, CA),
        value_class(B, CB),
        equal_class(CA, CB, R)
    ).

equal_class(number(_, X), number(_, Y), R) :- !, truth_of(X =:= Y, R).
equal_class(string(X, _), string(Y, _), R) :- !, truth_of(X == Y, R).
equal_class(boolean(X), boolean(Y), R) :- !, truth_of(X == Y, R).
equal_class(datetime(T, X, ZX), datetime(T, Y, ZY), R) :-
    !,
    datetime_order(X, ZX, Y, ZY, O),
    truth_of(O == (=), R).
equal_class(datetime(_, _, _), datetime(_, _, _), false) :- !.
equal_class(lang(X, TX), lang(Y, TY), R) :-
    !,
    downcase_atom(TX, LX),
    downcase_atom(TY, LY),
    truth_of(( X == Y, LX == LY ), R).
equal_class(lang(_, _), _, false) :- !.
equal_class(_, lang(_, _), false) :- !.
equal_class(iri(X), iri(Y), R) :- !, truth_of(X == Y, R).
equal_class(iri(_), _, false) :- !.
equal_class(_, iri(_), false) :- !.
equal_class(bnode(X), bnode(Y), R) :- !, truth_of(X == Y, R).
equal_class(bnode(_), _, false) :- !.
equal_class(_, bnode(_), false) :- !.
equal_class(typed(T, X), typed(T, Y), true) :-
    X == Y,
    !.
equal_class(invalid(T, X), invalid(T, Y), true) :-
    X == Y.

truth_of(Goal, R) :-
    (   call(Goal)
    ->  R = true
    ;   R = false
    ).

%   Arithmetic with numeric type promotion.

arithmetic(add(A, B), Mu, Ctx, V) :- binary(+, A, B, Mu, Ctx, V).
arithmetic(sub(A, B), Mu, Ctx, V) :- binary(-, A, B, Mu, Ctx, V).
arithmetic(mul(A, B), Mu, Ctx, V) :- binary(*, A, B, Mu, Ctx, V).
arithmetic(divide(A, B), Mu, Ctx, V) :- binary(/, A, B, Mu, Ctx, V).
arithmetic(neg(A), Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    numeric(VA, K, N),
    R is -N,
    number_term(K, R, V).
arithmetic(pos(A), Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    numeric(VA, K, N),
    number_term(K, N, V).

binary(Op, A, B, Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    eval_expr(B, Mu, Ctx, VB),
    numeric(VA, KA, NA),
    numeric(VB, KB, NB),
    promote(KA, KB, K0),
    (   Op == (/), K0 == integer
    ->  K = decimal
    ;   K = K0
    ),
    catch(compute(Op, K, NA, NB, R), _, fail),
    number_term(K, R, V).

compute(+, _, A, B, R) :- R is A + B.
compute(-, _, A, B, R) :- R is A - B.
compute(*, _, A, B, R) :- R is A * B.
compute(/, K, A, B, R) :-
    (   memberchk(K, [float, double])
    ->  R is float(A) / float(B)
    ;   B =\= 0,
        (   rational(A),
            rational(B)
        ->  R is A rdiv B
        ;   R0 is A / B,
            (   integer(R0)
            ->  R = R0
            ;   R is float(R0)
            )
        )
    ).

promote(A, B, K) :-
    kind_rank(A, RA),
    kind_rank(B, RB),
    (   RA >= RB
    ->  K = A
    ;   K = B
    ).

numeric(T, Kind, N) :-
    value_class(T, number(Kind, N)).

%   number_term(+Kind, +N, -Literal)

number_term(integer, N, literal(type(T, Lex))) :-
    !,
    integer(N),
    rdf_equal(xsd:integer, T),
    atom_number(Lex, N).
number_term(decimal, N, literal(type(T, Lex))) :-
    !,
    rdf_equal(xsd:decimal, T),
    decimal_lexical(N, Lex).
number_term(Kind, N, Literal) :-
    F is float(N),
    double_lexical(F, Lex),
    kind_type(Kind, T),
    type_literal(T, Lex, Literal).

decimal_lexical(N, Lex) :-
    (   integer(N)
    ->  format(atom(Lex), '~d.0', [N])
    ;   rational(N)
    ->  rational_lexical(N, Lex)
    ;   N =:= float_integer_part(N),
        abs(N) < 1.0e15
    ->  I is integer(N),
        format(atom(Lex), '~d.0', [I])
    ;   format(atom(Lex0), '~15f', [N]),
        atom_codes(Lex0, Codes0),
        reverse(Codes0, R0),
        strip_zeros(R0, R),
        reverse(R, Codes),
        atom_codes(Lex, Codes)
    ).

%   rational_lexical(+N, -Lex): the decimal digits of the rational N,
%   exact when it has at most 30 after the point, else rounded to 20.

rational_lexical(N, Lex) :-
    (   between(1, 30, Scale),
        Scaled is N * 10^Scale,
        integer(Scaled)
    ->  true
    ;   Scale = 20,
        Scaled is round(N * 10^Scale)
    ),
    Abs is abs(Scaled),
    format(atom(Digits0), '~d', [Abs]),
    atom_length(Digits0, Len),
    (   Len =< Scale
    ->  Pad is Scale - Len + 1,
        length(Zeros, Pad),
        maplist(=(0'0), Zeros),
        atom_codes(ZeroAtom, Zeros),
        atom_concat(ZeroAtom, Digits0, Digits)
    ;   Digits = Digits0
    ),
    atom_length(Digits, DLen),
    IntLen is DLen - Scale,
    sub_atom(Digits, 0, IntLen, _, IntPart),
    sub_atom(Digits, IntLen, Scale, 0, FracPart0),
    atom_codes(FracPart0, FCodes0),
    reverse(FCodes0, RF0),
    strip_zeros_all(RF0, RF),
    reverse(RF, FCodes),
    (   FCodes == []
    ->  FracPart = '0'
    ;   atom_codes(FracPart, FCodes)
    ),
    (   Scaled < 0
    ->  Sign = '-'
    ;   Sign = ''
    ),
    atomic_list_concat([Sign, IntPart, '.', FracPart], Lex).

strip_zeros_all([0'0|T], R) :-
    !,
    strip_zeros_all(T, R).
strip_zeros_all(R, R).

strip_zeros([0'0, C|T], R) :-
    C \== 0'.,
    !,
    strip_zeros([C|T], R).
strip_zeros(R, R).

double_lexical(F, Lex) :-
    (   F =\= F
    ->  Lex = 'NaN'
    ;   F =:= inf
    ->  Lex = 'INF'
    ;   F =:= -inf
    ->  Lex = '-INF'
    ;   format(atom(Lex), '~w', [F])
    ).

		 /*******************************
		 *           FUNCTIONS          *
		 *******************************/

%   function(+Name, +Values, -Value) is semidet.

function(str, [X], V) :-
    (   X = literal(_)
    ->  literal_lexical(X, Lex)
    ;   atom(X),
        \+ rdf_is_bnode(X),
        Lex = X
    ),
    V = literal(Lex).
function(lang, [literal(L)], literal(Tag)) :-
    (   L = lang(Tag0, _)
    ->  Tag = Tag0
    ;   Tag = ''
    ).
function(datatype, [literal(L)], T) :-
    (   L = type(T0, _)
    ->  T = T0
    ;   L = lang(_, _)
    ->  rdf_equal(rdf:langString, T)
    ;   rdf_equal(xsd:string, T)
    ).
function(iri(Base), [X], IRI) :-
    to_iri(X, Base, IRI).
function(isiri, [X], V) :-
    truth_of(( atom(X), \+ rdf_is_bnode(X) ), R),
    boolean_term(R, V).
function(isuri, [X], V) :-
    function(isiri, [X], V).
function(isblank, [X], V) :-
    truth_of(( atom(X), rdf_is_bnode(X) ), R),
    boolean_term(R, V).
function(isliteral, [X], V) :-
    truth_of(X = literal(_), R),
    boolean_term(R, V).
function(isnumeric, [X], V) :-
    truth_of(numeric(X, _, _), R),
    boolean_term(R, V).
function(now, [], literal(type(T, Lex))) :-
    rdf_equal(xsd:dateTime, T),
    get_time(Now),
    format_time(atom(Lex), '%FT%T.%3f%:z', Now).
function(rand, [], V) :-
    X is random_float,
    number_term(double, X, V).
function(uuid, [], IRI) :-
    uuid(UUID, [version(4)]),
    atom_concat('urn:uuid:', UUID, IRI).
function(struuid, [], literal(UUID)) :-
    uuid(UUID, [version(4)]).
function(bnode, [], BNode) :-
    rdf_bnode(BNode).
function(md5, [X], literal(Hex)) :-
    simple_string(X, Lex),
    md5_hash(Lex, Hex, [encoding(utf8)]).
function(Name, [X], literal(Hex)) :-
    sha_algorithm(Name, Algorithm),
    !,
    simple_string(X, Lex),
    sha_hash(Lex, Hash, [algorithm(Algorithm), encoding(utf8)]),
    hash_atom(Hash, Hex).
function(Field, [X], V) :-
    date_field(Field),
    !,
    date_time_parts(X, Parts),
    date_field_value(Field, Parts, V).
function(sameterm, [X, Y], V) :-
    truth_of(X == Y, R),
    boolean_term(R, V).
function(langmatches, [T, Range], V) :-
    simple_string(T, Tag),
    simple_string(Range, R0),
    downcase_atom(Tag, LTag),
    downcase_atom(R0, LRange),
    truth_of(tag_matches(LTag, LRange), R),
    boolean_term(R, V).
function(strlen, [X], V) :-
    string_arg(X, Lex, _),
    atom_length(Lex, N),
    number_term(integer, N, V).
function(ucase, [X], V) :-
    string_arg(X, Lex, Tag),
    upcase_atom(Lex, Up),
    string_term(Tag, Up, V).
function(lcase, [X], V) :-
    string_arg(X, Lex, Tag),
    downcase_atom(Lex, Low),
    string_term(Tag, Low, V).
function(contains, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, _, _, _, B), R),
    boolean_term(R, V).
function(strstarts, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, 0, _, _, B), R),
    boolean_term(R, V).
function(strends, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, _, _, 0, B), R),
    boolean_term(R, V).
function(strbefore, [X, Y], V) :-
    compatible_args(X, Y, A, B, Tag),
    (   sub_atom(A, Before, _, _, B)
    ->  sub_atom(A, 0, Before, _, Sub),
        string_term(Tag, Sub, V)
    ;   V = literal('')
    ).
function(strafter, [X, Y], V) :-
    compatible_args(X, Y, A, B, Tag),
    (   sub_atom(A, _, _, After, B)
    ->  sub_atom(A, _, After, 0, Sub),
        string_term(Tag, Sub, V)
    ;   V = literal('')
    ).
function(substr, [X, Start|Len], V) :-
    string_arg(X, Lex, Tag),
    numeric(Start, _, S0),
    S is round(S0),
    atom_length(Lex, N),
    (   Len = [L]
    ->  numeric(L, _, L0),
        E is S + round(L0)
    ;   E is N + 1
    ),
    From is max(1, S),
    To is min(N + 1, E),
    (   To > From
    ->  B is From - 1,
        Count is To - From,
        sub_atom(Lex, B, Count, _, Sub)
    ;   Sub = ''
    ),
    string_term(Tag, Sub, V).
function(concat, Args, V) :-
    maplist(string_arg_tag, Args, Lexes, Tags),
    atomic_list_concat(Lexes, Lex),
    (   Tags = [T|Ts],
        forall(member(T1, Ts), T1 == T),
        T \== simple
    ->  string_term(T, Lex, V)
    ;   V = literal(Lex)
    ).
function(encode_for_uri, [X], literal(Enc)) :-
    string_arg(X, Lex, _),
    encode_for_uri(Lex, Enc).
function(strlang, [X, L], literal(lang(Tag, Lex))) :-
    string_arg(X, Lex, Kind),
    Kind \= lang(_),
    simple_string(L, Tag),
    Tag \== ''.
function(strdt, [X, T], literal(type(T, Lex))) :-
    string_arg(X, Lex, Kind),
    Kind \= lang(_),
    atom(T),
    \+ rdf_is_bnode(T).
function(abs, [X], V) :-
    numeric(X, K, N),
    R is abs(N),
    number_term(K, R, V).
function(ceil, [X], V) :-
    numeric(X, K, N),
    rounded(ceiling, K, N, R),
    number_term(K, R, V).
function(floor, [X], V) :-
    numeric(X, K, N),
    rounded(floor, K, N, R),
    number_term(K, R, V).
function(round, [X], V) :-
    numeric(X, K, N),
    rounded(round, K, N, R),
    number_term(K, R, V).
function(regex, [X, P|Flags], V) :-
    string_arg(X, Text, _),
    simple_string(P, Pattern),
    flags_arg(Flags, FlagText),
    regex_match(Text, Pattern, FlagText, R),
    boolean_term(R, V).
function(replace, [X, P, W|Flags], V) :-
    string_arg(X, Text, Tag),
    simple_string(P, Pattern),
    simple_string(W, With),
    flags_arg(Flags, FlagText),
    regex_replace(Text, Pattern, With, FlagText, Result),
    string_term(Tag, Result, V).
function(cast(Kind), [X], V) :-
    cast(Kind, X, V).

tag_matches(Tag, '*') :-
    !,
    Tag \== ''.
tag_matches(Tag, Range) :-
    (   Tag == Range
    ->  true
    ;   atom_concat(Range, '-', Prefix),
        sub_atom(Tag, 0, _, _, Prefix)
    ).

rounded(_, integer, N, N) :- !.
rounded(round, _, N, R) :-
    !,
    R0 is floor(N + 0.5),
    R is float(R0).
rounded(F, _, N, R) :-
    G =.. [F, N],
    R0 is G,
    R is float(R0).

literal_lexical(literal(L), Lex) :-
    (   L = type(_, Lex0)
    ->  true
    ;   L = lang(_, Lex0)
    ->  true
    ;   Lex0 = L
    ),
    lexical_atom(Lex0, Lex).

%   to_iri(+X, +Base, -IRI): IRI() of X: a relative IRI is resolved
%   against Base, or without BASE (`none`) is a name of oro's default
%   namespace, as relative IRIs of the query text are.

to_iri(X, Base, IRI) :-
    (   atom(X)
    ->  \+ rdf_is_bnode(X),
        IRI = X
    ;   string_arg(X, Lex, Tag),
        Tag \= lang(_),
        (   uri_is_global(Lex)
        ->  IRI = Lex
        ;   Base \== none
        ->  uri_resolve(Lex, Base, IRI)
        ;   oro_default_namespace(NS),
            atom_concat(NS, Lex, IRI)
        )
    ).

%   String arguments (SPARQL 1.1 §17.4.3): simple literals, xsd:string
%   and language-tagged literals; Tag is simple, xsd or lang(L).

string_arg(literal(L), Lex, Tag) :-
    (   L = type(T, Lex0)
    ->  xsd_string(T),
        Tag = xsd
    ;   L = lang(Lang, Lex0)
    ->  Tag = lang(Lang)
    ;   Lex0 = L,
        Tag = simple
    ),
    lexical_atom(Lex0, Lex).

string_arg_tag(X, Lex, Tag) :-
    string_arg(X, Lex, Tag).

simple_string(X, Lex) :-
    string_arg(X, Lex, Tag),
    Tag \= lang(_).

string_term(simple, Lex, literal(Lex)).
string_term(xsd, Lex, literal(type(T, Lex))) :-
    rdf_equal(xsd:string, T).
string_term(lang(L), Lex, literal(lang(L, Lex))).

compatible_args(X, Y, A, B, Tag) :-
    string_arg(X, A, Tag),
    string_arg(Y, B, TagY),
    (   TagY \= lang(_)
    ->  true
    ;   TagY = lang(LY),
        Tag = lang(LX),
        downcase_atom(LX, L),
        downcase_atom(LY, L)
    ).

flags_arg([], '').
flags_arg([F], Flags) :-
    simple_string(F, Flags).

encode_for_uri(Lex, Enc) :-
    atom_codes(Lex, Codes),
    phrase(percent_encoded(Codes), EncCodes),
    atom_codes(Enc, EncCodes).

percent_encoded([]) --> [].
percent_encoded([C|Cs]) -->
    (   { C < 128, ( code_type(C, alnum) ; memberchk(C, `-_.~`) ) }
    ->  [C]
    ;   { utf8_bytes(C, Bytes) },
        percent_bytes(Bytes)
    ),
    percent_encoded(Cs).

utf8_bytes(C, [C]) :- C < 0x80, !.
utf8_bytes(C, [B1, B2]) :-
    C < 0x800,
    !,
    B1 is 0xC0 \/ (C >> 6),
    B2 is 0x80 \/ (C /\ 0x3F).
utf8_bytes(C, [B1, B2, B3]) :-
    C < 0x10000,
    !,
    B1 is 0xE0 \/ (C >> 12),
    B2 is 0x80 \/ ((C >> 6) /\ 0x3F),
    B3 is 0x80 \/ (C /\ 0x3F).
utf8_bytes(C, [B1, B2, B3, B4]) :-
    B1 is 0xF0 \/ (C >> 18),
    B2 is 0x80 \/ ((C >> 12) /\ 0x3F),
    B3 is 0x80 \/ ((C >> 6) /\ 0x3F),
    B4 is 0x80 \/ (C /\ 0x3F).

percent_bytes([]) --> [].
percent_bytes([B|Bs]) -->
    { format(codes(Hex), '%~|~`0t~16R~2+', [B]) },
    Hex,
    percent_bytes(Bs).

%   labelled_bnode(+Mu, +Lex, -BNode): BNODE(Lex) in the solution Mu:
%   the same blank node for the same string in the same solution, a
%   different one in any other solution (SPARQL 1.1 §17.4.2.9).  Its
%   label is a digest of both, so it is new to the store; labels are
%   scoped to one result set, where distinct solutions give distinct
%   labels.  The solution is its bindings less those made by BNODE,
%   so that two BNODE(?s) of one SELECT agree when their ?s do.

labelled_bnode(Mu, Lex, BNode) :-
    exclude(made_bnode_binding, Mu, Mu1),
    msort(Mu1, Key),
    variant_sha1(Key-Lex, Hash),
    atom_concat('_:sparql-bnode-', Hash, BNode).

made_bnode_binding(_-V) :-
    atom(V),
    sub_atom(V, 0, _, _, '_:sparql-bnode-').

%   XSD casts (SPARQL 1.1 §17.5).

cast(string, X, V) :-
    (   X = literal(type(_, _)),
        value_class(X, C),
        canonical_string(C, Lex)
    ->  true
    ;   function(str, [X], literal(Lex))
    ),
    string_term(xsd, Lex, V).

cast(boolean, X, V) :-
    (   value_class(X, boolean(B))
    ->  true
    ;   numeric(X, _, N)
    ->  (   ( N =:= 0 ; N =\= N )
        ->  B = false
        ;   B = true
        )
    ;   simple_string(X, Lex),
        boolean_lexical(Lex, B)
    ),
    boolean_term(B, V).
cast(dateTime, X, literal(type(T, Lex))) :-
    rdf_equal(xsd:dateTime, T),
    (   X = literal(type(T, Lex))
    ->  true
    ;   simple_string(X, Lex0),
        normalize_space(atom(Lex), Lex0),
        atom_codes(Lex, Codes),
        phrase(xsd_date_time, Codes),
        date_stamp(Lex, _)
    ).
cast(Kind, X, V) :-
    memberchk(Kind, [integer, decimal, float, double]),
    (   value_class(X, boolean(B))
    ->  (   B == true -> N0 = 1 ; N0 = 0 )
    ;   numeric(X, _, N0)
    ->  true
    ;   simple_string(X, Lex),
        normalize_space(atom(Lex1), Lex),
        lexical_number(Kind, Lex1, N0)
    ),
    cast_number(Kind, N0, N),
    number_term(Kind, N, V).


%   canonical_string(+Class, -Lex): the canonical lexical form XPath
%   casts a number or boolean to xsd:string with: 1.0 is "1", "1E0"
%   of a double "1", "0"^^xsd:boolean "false"; a double or float
%   outside [1e-6, 1e6) keeps an exponent ("1.0E7").

canonical_string(boolean(B), B).
canonical_string(number(integer, N), Lex) :-
    format(atom(Lex), '~d', [N]).
canonical_string(number(decimal, N), Lex) :-
    decimal_lexical(N, Lex0),
    drop_point_zero(Lex0, Lex).
canonical_string(number(Kind, N), Lex) :-
    memberchk(Kind, [float, double]),
    F is float(N),
    (   F =:= F,
        A is abs(F),
        ( A =:= 0 ; A >= 1.0e-6, A < 1.0e6 )
    ->  decimal_lexical(F, Lex0),
        drop_point_zero(Lex0, Lex)
    ;   F =:= F, F =\= inf, F =\= -inf
    ->  format(atom(Sci), '~15e', [F]),
        atomic_list_concat([Mantissa0, Exp0], e, Sci),
        mantissa_digits(Mantissa0, Mantissa),
        atom_number(Exp0, Exp),
        format(atom(Lex), '~wE~d', [Mantissa, Exp])
    ;   double_lexical(F, Lex)
    ).

mantissa_digits(M0, M) :-
    (   atom_concat(M1, '0', M0),
        \+ atom_concat(_, '.', M1)
    ->  mantissa_digits(M1, M)
    ;   M = M0
    ).

drop_point_zero(Lex0, Lex) :-
    (   atom_concat(Lex1, '.0', Lex0)
    ->  Lex = Lex1
    ;   Lex = Lex0
    ).

cast_number(integer, N0, N) :-
    !,
    N0 =:= N0,
    N0 =\= inf, N0 =\= -inf,
    N is truncate(N0).
cast_number(decimal, N0, N) :-
    !,
    N0 =:= N0,
    N0 =\= inf, N0 =\= -inf,
    N = N0.
cast_number(_, N0, N) :-
    N is float(N0).

sha_algorithm(sha1, sha1).
sha_algorithm(sha256, sha256).
sha_algorithm(sha384, sha384).
sha_algorithm(sha512, sha512).

%   The accessors of xsd:dateTime values: YEAR, MONTH, DAY, HOURS,
%   MINUTES (integers), SECONDS (a decimal), TIMEZONE (an
%   xsd:dayTimeDuration; an error without a time zone) and TZ (the
%   time zone as written, "" without one), read from the lexical form.

date_field(year).
date_field(month).
date_field(day).
date_field(hours).
date_field(minutes).
date_field(seconds).
date_field(timezone).
date_field(tz).

%   date_time_parts(+Term, -Parts): Parts is dt(Y, Mo, D, H, Mi, S, TZ)
%   of an xsd:dateTime literal, S an atom, TZ an atom ('' for none).

date_time_parts(literal(type(T, Lex0)), dt(Y, Mo, D, H, Mi, S, TZ)) :-
    rdf_equal(xsd:dateTime, T),
    lexical_atom(Lex0, Lex),
    sub_atom(Lex, Before, 1, _, 'T'),
    !,
    sub_atom(Lex, 0, Before, _, Date),
    After is Before + 1,
    sub_atom(Lex, After, _, 0, Time0),
    (   sub_atom(Time0, _, 1, 0, 'Z')
    ->  TZ = 'Z',
        sub_atom(Time0, 0, _, 1, Time)
    ;   sub_atom(Time0, B, 6, 0, TZ0),
        sub_atom(TZ0, 0, 1, _, Sign),
        memberchk(Sign, [+, -])
    ->  TZ = TZ0,
        sub_atom(Time0, 0, B, _, Time)
    ;   TZ = '',
        Time = Time0
    ),
    atomic_list_concat([YA, MoA, DA], -, Date),
    atomic_list_concat([HA, MiA, S], :, Time),
    maplist(atom_number, [YA, MoA, DA, HA, MiA], [Y, Mo, D, H, Mi]).

date_field_value(year, dt(Y, _, _, _, _, _, _), V) :-
    number_term(integer, Y, V).
date_field_value(month, dt(_, Mo, _, _, _, _, _), V) :-
    number_term(integer, Mo, V).
date_field_value(day, dt(_, _, D, _, _, _, _), V) :-
    number_term(integer, D, V).
date_field_value(hours, dt(_, _, _, H, _, _, _), V) :-
    number_term(integer, H, V).
date_field_value(minutes, dt(_, _, _, _, Mi, _, _), V) :-
    number_term(integer, Mi, V).
date_field_value(seconds, dt(_, _, _, _, _, S, _), V) :-
    lexical_number(decimal, S, N),
    number_term(decimal, N, V).
date_field_value(tz, dt(_, _, _, _, _, _, TZ), literal(TZ)).
date_field_value(timezone, dt(_, _, _, _, _, _, TZ), literal(type(T, Duration))) :-
    TZ \== '',
    rdf_equal(xsd:dayTimeDuration, T),
    (   TZ == 'Z'
    ->  Duration = 'PT0S'
    ;   sub_atom(TZ, 0, 1, _, Sign),
        sub_atom(TZ, 1, 2, _, HA),
        sub_atom(TZ, 4, 2, _, MA),
        atom_number(HA, H),
        atom_number(MA, M),
        (   Sign == (-)
        ->  Prefix = '-PT'
        ;   Prefix = 'PT'
        ),
        (   H =:= 0, M =:= 0
        ->  Duration = 'PT0S'
        ;   M =:= 0
        ->  format(atom(Duration), '~w~dH', [Prefix, H])
        ;   H =:= 0
        ->  format(atom(Duration), '~w~dM', [Prefix, M])
        ;   format(atom(Duration), '~w~dH~dM', [Prefix, H, M])
        )
    ).

%   Regular expressions (XPath syntax, run by PCRE).

regex_options(Flags, Options, Quote) :-
    atom_codes(Flags, Codes),
    foldl(regex_flag, Codes, opts([], false), opts(Options, Quote)).

regex_flag(0'i, opts(O, Q), opts([caseless(true)|O], Q)).
regex_flag(0's, opts(O, Q), opts([dotall(true)|O], Q)).
regex_flag(0'm, opts(O, Q), opts([multiline(true)|O], Q)).
regex_flag(0'x, opts(O, Q), opts([extended(true)|O], Q)).
regex_flag(0'q, opts(O, _), opts(O, true)).

regex_pattern(Pattern0, Quote, Pattern) :-
    (   Quote == true
    ->  atom_codes(Pattern0, Codes0),
        foldl(quote_code, Codes0, Codes, []),
        string_codes(Pattern, Codes)
    ;   atom_string(Pattern0, Pattern)
    ).

quote_code(C, [0'\\, C|T], T) :-
    memberchk(C, `\\^$.|?*+()[]{}`),
    !.
quote_code(C, [C|T], T).

:- if(current_predicate(re_match/3)).

regex_match(Text, Pattern0, Flags, R) :-
    regex_options(Flags, Options, Quote),
    regex_pattern(Pattern0, Quote, Pattern),
    atom_string(Text, String),
    catch(( re_match(Pattern, String, Options)
          ->  R = true
          ;   R = false
          ),
          _, fail).

%   regex_replace(+Text, +Pattern, +With, +Flags, -Result) is semidet.
%
%   fn:replace: every match of Pattern in Text replaced by With, whose
%   $N is the text of group N (empty when the group took no part in the
%   match) and \$, \\ a dollar and a backslash.  The substitution is
%   ours: re_replace/5 of SWI-Prolog 9.0.4 raises on a group that did
%   not match.  Fails (an error) on a bad replacement or a pattern that
%   matches the empty string, as XPath says.

regex_replace(Text, Pattern0, With, Flags, Result) :-
    regex_options(Flags, Options, Quote),
    regex_pattern(Pattern0, Quote, Pattern),
    atom_string(Text, String),
    atom_codes(With, WithCodes),
    phrase(replacement(Parts), WithCodes),
    catch(re_foldl(replace_match(String, Parts), Pattern, String,
                   0-Codes, End-Tail, [capture_type(range)|Options]),
          _, fail),
    string_length(String, Length),
    Rest is Length - End,
    sub_string(String, End, Rest, _, After),
    string_codes(After, Tail),
    atom_codes(Result, Codes).

replace_match(String, Parts, Match, Start-Codes, End-Tail) :-
    get_dict(0, Match, From-Len),
    Len > 0,
    Before is From - Start,
    sub_string(String, Start, Before, _, Prefix),
    string_codes(Prefix, PrefixCodes),
    append(PrefixCodes, Codes1, Codes),
    foldl(replacement_part(String, Match), Parts, Codes1, Tail),
    End is From + Len.

replacement_part(_, _, text(C), [C|T], T).
replacement_part(String, Match, group(N), Codes, Tail) :-
    (   get_dict(N, Match, From-Len)
    ->  sub_string(String, From, Len, _, Group),
        string_codes(Group, GroupCodes),
        append(GroupCodes, Tail, Codes)
    ;   Codes = Tail
    ).

replacement([Part|Parts]) -->
    replacement_part(Part),
    !,
    replacement(Parts).
replacement([]) --> [].

replacement_part(text(0'$)) --> "\\$", !.
replacement_part(text(0'\\)) --> "\\\\", !.
replacement_part(group(N)) -->
    "$",
    !,
    digits(Ds),
    { Ds \== [], number_codes(N, Ds) }.
replacement_part(text(C)) -->
    [C],
    { C \== 0'\\ }.

:- else.

regex_match(_, _, _, _) :-
    fail.
regex_replace(_, _, _, _, _) :-
    fail.

:- endif.

		 /*******************************
		 *          AGGREGATES          *
		 *******************************/

%   aggregate_value(+Name, +Distinct, +Arg, +Sep, +Members, +Ctx, -Value)

aggregate_value(count, Distinct, star, _, Members, _, V) :-
    !,
    (   Distinct == distinct
    ->  sort(Members, Ms)
    ;   Ms = Members
    ),
    length(Ms, N),
    number_term(integer, N, V).
aggregate_value(Name, Distinct, Arg, Sep, Members, Ctx, V) :-
    findall(R, ( member(Mu, Members),
                 (   eval_expr(Arg, Mu, Ctx, X)
                 ->  R = ok(X)
                 ;   R = error
                 )
               ), Results),
    (   Distinct == distinct
    ->  list_to_set(Results, Results1)
    ;   Results1 = Results
    ),
    aggregate_results(Name, Results1, Sep, V).

aggregate_results(count, Results, _, V) :-
    aggregate_all(count, member(ok(_), Results), N),
    number_term(integer, N, V).
aggregate_results(sum, Results, _, V) :-
    \+ memberchk(error, Results),
    foldl(sum_value, Results, integer-0, K-N),
    number_term(K, N, V).
aggregate_results(avg, Results, _, V) :-
    \+ memberchk(error, Results),
    (   Results == []
    ->  number_term(integer, 0, V)
    ;   foldl(sum_value, Results, integer-0, K0-Sum),
        length(Results, Count),
        promote(K0, decimal, K),
        (   rational(Sum)
        ->  Avg is Sum rdiv Count
        ;   Avg is Sum / Count
        ),
        number_term(K, Avg, V)
    ).
aggregate_results(min, Results, _, V) :-
    findall(X, member(ok(X), Results), [X0|Xs]),
    foldl(min_value, Xs, X0, V).
aggregate_results(max, Results, _, V) :-
    findall(X, member(ok(X), Results), [X0|Xs]),
    foldl(max_value, Xs, X0, V).
aggregate_results(sample, Results, _, V) :-
    memberchk(ok(V), Results).
aggregate_results(group_concat, Results, Sep, literal(Lex)) :-
    findall(S, ( member(ok(X), Results),
                 function(str, [X], literal(S))
               ), Strings),
    atomic_list_concat(Strings, Sep, Lex).

sum_value(ok(X), K0-N0, K-N) :-
    numeric(X, KX, NX),
    promote(K0, KX, K),
    N is N0 + NX.

min_value(X, V0, V) :-
    term_order(X, V0, O),
    (   O == (<)
    ->  V = X
    ;   V = V0
    ).

max_value(X, V0, V) :-
    term_order(X, V0, O),
    (   O == (>)
    ->  V = X
    ;   V = V0
    ).

