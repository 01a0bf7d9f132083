:- module(oro_sparql_expressions,
          [ expression//2,              % +St, -Expr
            constraint//2,              % +St, -Expr
            bracketted_expression//2,   % +St, -Expr
            function_constraint//2      % +St, -Expr
          ]).
:- multifile
    exists_pattern//2.
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/sparql/oro_sparql_syntax)).
:- use_module(library(oro/sparql/oro_sparql_triples), [iri//2, rdf_literal//2, boolean_literal//1]).
:- use_module(library(oro/sparql/oro_sparql_functions), [kind_type/2, cast_type/2]).

/** <module> The SPARQL grammar: expressions

The expression productions of the W3C SPARQL 1.1 grammar, from
Expression down to the built-in calls (with their arity checks), the
function calls, casts and aggregates, producing the expression terms
of the SPARQL algebra (oro_sparql:oro_sparql_parse/2).
*/

%!  exists_pattern(+St, -Pattern)// is semidet.
%
%   Hook: Pattern is the group graph pattern of EXISTS or NOT EXISTS.
%   oro_sparql_grammar, where graph patterns are parsed, defines it:
%   this module does not import the grammar that imports it.

		 /*******************************
		 *    PARSING: EXPRESSIONS      *
		 *******************************/

%   Expressions: var(N), const(Term), or/2, and/2, not/1, cmp(Op,A,B),
%   in(E, List), not_in(E, List), add/2, sub/2, mul/2, divide/2,
%   neg/1, pos/1, fn(Name, Args), bound(N), exists(P), not_exists(P),
%   agg(Name, Distinct, Arg, Separator).

%!  constraint(+St, -Expr)// is semidet.
%!  bracketted_expression(+St, -Expr)// is semidet.
%!  function_constraint(+St, -Expr)// is semidet.
%!  expression(+St, -Expr)// is semidet.
%
%   Expr is the expression of a Constraint (of a FILTER: bracketted, a
%   built-in call or a function call), of a BrackettedExpression, of a
%   FunctionCall (a built-in or a function IRI), of an Expression.

constraint(St, E) -->
    (   peek_punct('(')
    ->  bracketted_expression(St, E)
    ;   function_constraint(St, E)
    ).

function_constraint(St, E) -->
    (   builtin_call(St, E)
    ->  []
    ;   iri_function(St, E)
    ).

bracketted_expression(St, E) -->
    tok(punct('(')),
    expression(St, E),
    tok(punct(')')).

expression(St, E) -->
    and_expression(St, E0),
    or_rest(St, E0, E).

or_rest(St, E0, E) -->
    (   tok(punct('||'))
    ->  and_expression(St, E1),
        or_rest(St, or(E0, E1), E)
    ;   { E = E0 }
    ).

and_expression(St, E) -->
    relational_expression(St, E0),
    and_rest(St, E0, E).

and_rest(St, E0, E) -->
    (   tok(punct('&&'))
    ->  relational_expression(St, E1),
        and_rest(St, and(E0, E1), E)
    ;   { E = E0 }
    ).

relational_expression(St, E) -->
    additive_expression(St, A),
    (   relational_operator(Op)
    ->  additive_expression(St, B),
        { E = cmp(Op, A, B) }
    ;   kw(in)
    ->  expression_list(St, L),
        { E = in(A, L) }
    ;   kw(not)
    ->  kw(in),
        expression_list(St, L),
        { E = not_in(A, L) }
    ;   { E = A }
    ).

relational_operator(Op) -->
    { member(Op, [=, '!=', <, >, '<=', '>=']) },
    tok(punct(Op)),
    !.

additive_expression(St, E) -->
    multiplicative_expression(St, E0),
    additive_rest(St, E0, E).

additive_rest(St, E0, E) -->
    (   tok(punct(+))
    ->  multiplicative_expression(St, E1),
        additive_rest(St, add(E0, E1), E)
    ;   tok(punct(-))
    ->  multiplicative_expression(St, E1),
        additive_rest(St, sub(E0, E1), E)
    ;   { E = E0 }
    ).

multiplicative_expression(St, E) -->
    unary_expression(St, E0),
    multiplicative_rest(St, E0, E).

multiplicative_rest(St, E0, E) -->
    (   tok(punct(*))
    ->  unary_expression(St, E1),
        multiplicative_rest(St, mul(E0, E1), E)
    ;   tok(punct(/))
    ->  unary_expression(St, E1),
        multiplicative_rest(St, divide(E0, E1), E)
    ;   { E = E0 }
    ).

unary_expression(St, E) -->
    (   tok(punct(!))
    ->  primary_expression(St, E0),
        { E = not(E0) }
    ;   tok(punct(+))
    ->  primary_expression(St, E0),
        { E = pos(E0) }
    ;   tok(punct(-))
    ->  primary_expression(St, E0),
        { E = neg(E0) }
    ;   primary_expression(St, E)
    ).

primary_expression(St, E) -->
    (   tok(punct('('))
    ->  expression(St, E),
        tok(punct(')'))
    ;   tok(var(N))
    ->  { E = var(N) }
    ;   rdf_literal(St, T)
    ->  { E = const(T) }
    ;   tok(num(Kind, Lex))
    ->  { kind_type(Kind, Type),
          E = const(literal(type(Type, Lex)))
        }
    ;   boolean_literal(T)
    ->  { E = const(T) }
    ;   builtin_call(St, E)
    ->  []
    ;   iri_or_function(St, E)
    ).

expression_list(St, L) -->
    tok(punct('(')),
    (   tok(punct(')'))
    ->  { L = [] }
    ;   expression(St, E),
        expression_list_rest(St, Es),
        tok(punct(')')),
        { L = [E|Es] }
    ).

expression_list_rest(St, [E|Es]) -->
    tok(punct(',')),
    !,
    expression(St, E),
    expression_list_rest(St, Es).
expression_list_rest(_, []) --> [].

iri_or_function(St, E) -->
    here(P),
    iri(St, IRI),
    (   peek_punct('(')
    ->  expression_list(St, Args),
        { function_iri(IRI, Args, P, E) }
    ;   { E = const(IRI) }
    ).

iri_function(St, E) -->
    here(P),
    iri(St, IRI),
    expression_list(St, Args),
    { function_iri(IRI, Args, P, E) }.

function_iri(IRI, Args, P, E) :-
    (   cast_type(IRI, Kind)
    ->  (   Args = [A]
        ->  E = fn(cast(Kind), [A])
        ;   oro_iri_name(IRI, Name),
            semantic_error("~w takes one argument", [Name], P)
        )
    ;   E = fn(extension(IRI), Args)     % unknown: an error when evaluated
    ).

%   Built-in calls: a keyword followed by its arguments.

builtin_call(St, E) -->
    tokp(word(Name, Word), P),
    builtin(Name, Word, P, St, E).

builtin(exists, _, _, St, exists(P)) -->
    !,
    exists_pattern(St, P).
builtin(not, _, _, St, not_exists(P)) -->
    !,
    kw(exists),
    exists_pattern(St, P).
builtin(bound, _, _, _, bound(N)) -->
    !,
    tok(punct('(')),
    tok(var(N)),
    tok(punct(')')).
builtin(Name, Word, P, St, agg(Name, Distinct, Arg, Sep)) -->
    { aggregate_name(Name) },
    !,
    { (   St = st(_, _, _, aggregates)
      ->  true
      ;   upcase_atom(Word, Up),
          semantic_error("Aggregate ~w is not allowed here", [Up], P)
      ),
      no_aggregates(St, St1)
    },
    tok(punct('(')),
    (   kw(distinct)
    ->  { Distinct = distinct }
    ;   { Distinct = all }
    ),
    (   { Name == count },
        tok(punct(*))
    ->  { Arg = star }
    ;   expression(St1, Arg)
    ),
    (   { Name == group_concat },
        tok(punct(;))
    ->  kw(separator),
        tok(punct(=)),
        tok(str(Sep))
    ;   { Sep = ' ' }
    ),
    tok(punct(')')).
builtin(Name, Word, P, St, Function) -->
    { function_arity(Name, Min, Max) },
    !,
    expression_list(St, Args),
    { length(Args, N),
      (   N >= Min,
          ( Max == inf -> true ; N =< Max )
      ->  true
      ;   upcase_atom(Word, Up),
          semantic_error("Wrong number of arguments (~d) for ~w", [N, Up], P)
      ),
      based_function(Name, St, Args, Function)
    }.

builtin(Name, Word, P, _, _) -->
    peek_punct('('),
    { \+ keyword(Name),
      upcase_atom(Word, Up),
      semantic_error("Unknown or unsupported function ~w", [Up], P)
    }.

%   based_function(+Name, +St, +Args, -Function): IRI() and URI() resolve
%   a relative IRI against the query's BASE: they become
%   fn(iri(Base), Args), Base `none` without BASE.

based_function(Name, st(_, Base, _, _), Args, Function) :-
    (   memberchk(Name, [iri, uri])
    ->  Function = fn(iri(Base), Args)
    ;   Function = fn(Name, Args)
    ).

keyword(Name) :-
    memberchk(Name, [ select, ask, construct, describe, where, from, named,
                      prefix, base, distinct, reduced, group, by, having,
                      order, asc, desc, limit, offset, values, optional,
                      filter, union, minus, bind, as, graph, service, undef,
                      in, not, exists, separator, a, true, false
                    ]).

aggregate_name(count).
aggregate_name(sum).
aggregate_name(min).
aggregate_name(max).
aggregate_name(avg).
aggregate_name(sample).
aggregate_name(group_concat).

%   function_arity(?Name, ?Min, ?Max)

function_arity(str, 1, 1).
function_arity(lang, 1, 1).
function_arity(langmatches, 2, 2).
function_arity(datatype, 1, 1).
function_arity(iri, 1, 1).
function_arity(uri, 1, 1).
function_arity(isiri, 1, 1).
function_arity(isuri, 1, 1).
function_arity(isblank, 1, 1).
function_arity(isliteral, 1, 1).
function_arity(isnumeric, 1, 1).
function_arity(regex, 2, 3).
function_arity(replace, 3, 4).
function_arity(contains, 2, 2).
function_arity(strstarts, 2, 2).
function_arity(strends, 2, 2).
function_arity(strbefore, 2, 2).
function_arity(strafter, 2, 2).
function_arity(strlen, 1, 1).
function_arity(substr, 2, 3).
function_arity(ucase, 1, 1).
function_arity(lcase, 1, 1).
function_arity(concat, 0, inf).
function_arity(encode_for_uri, 1, 1).
function_arity(strlang, 2, 2).
function_arity(strdt, 2, 2).
function_arity(abs, 1, 1).
function_arity(ceil, 1, 1).
function_arity(floor, 1, 1).
function_arity(round, 1, 1).
function_arity(if, 3, 3).
function_arity(coalesce, 0, inf).
function_arity(sameterm, 2, 2).
function_arity(year, 1, 1).
function_arity(month, 1, 1).
function_arity(day, 1, 1).
function_arity(hours, 1, 1).
function_arity(minutes, 1, 1).
function_arity(seconds, 1, 1).
function_arity(timezone, 1, 1).
function_arity(tz, 1, 1).
function_arity(md5, 1, 1).
function_arity(sha1, 1, 1).
function_arity(sha256, 1, 1).
function_arity(sha384, 1, 1).
function_arity(sha512, 1, 1).
function_arity(now, 0, 0).
function_arity(rand, 0, 0).
function_arity(uuid, 0, 0).
function_arity(struuid, 0, 0).
function_arity(bnode, 0, 1).
